"""A CSE 168 scene (.test) as a Mitsuba 3 scene: the yardstick of bench/convergence.

Mitsuba is never part of vkrt; it renders the same scene so that vkrt's converged images and
its speed can be compared with an independent, well-tested path tracer. This reads the subset
of the format that the comparison scenes use (camera, triangles, spheres, quad lights,
transforms, modified-Phong and GGX materials, maxdepth, russianroulette) and refuses the rest.

The modified Phong and GGX BRDFs of doc/path-tracing.md, "BRDFs" are not Mitsuba's (its rough
conductors and plastics weigh their lobes otherwise), so they are Python BSDFs here, sampled as
that document's "Direction sampling" says.

    import mitsuba as mi; mi.set_variant("llvm_ad_rgb")
    scene, spp = load("cornellNEE.test")     # mi.Scene, the scene's spp
"""
import math
import tempfile
from pathlib import Path

import mitsuba as mi
import drjit as dr

mi.set_variant("llvm_ad_rgb")   # before any class derives from Mitsuba's: they are per variant


class LobeAndCosine(mi.BSDF):
    """A BSDF sampled as doc/path-tracing.md's "Direction sampling" says: with probability t a
    direction from the subclass's lobe (`_lobe`), else cosine; `_f` and `_pdf` are the
    subclass's. kd and ks come from the properties; one-sided (black from behind)."""

    def __init__(self, props):
        mi.BSDF.__init__(self, props)
        self.kd = mi.Color3f(props["kd_r"], props["kd_g"], props["kd_b"])
        self.ks = mi.Color3f(props["ks_r"], props["ks_g"], props["ks_b"])
        avg_kd = (props["kd_r"] + props["kd_g"] + props["kd_b"]) / 3
        avg_ks = (props["ks_r"] + props["ks_g"] + props["ks_b"]) / 3
        self.ratio = avg_ks / (avg_kd + avg_ks) if avg_kd + avg_ks > 0 else 0.0
        flags = mi.BSDFFlags.DiffuseReflection | mi.BSDFFlags.GlossyReflection | mi.BSDFFlags.FrontSide
        self.m_components = [flags]
        self.m_flags = flags

    def _valid(self, si, wo):
        return (mi.Frame3f.cos_theta(si.wi) > 0) & (mi.Frame3f.cos_theta(wo) > 0)

    def sample(self, ctx, si, sample1, sample2, active=True):
        cosine = mi.warp.square_to_cosine_hemisphere(sample2)
        wo = dr.select(sample1 < self.t, self._lobe(si.wi, sample2), cosine)
        bs = mi.BSDFSample3f()
        bs.wo = wo
        bs.pdf = self._pdf(si.wi, wo)
        bs.eta = 1.0
        bs.sampled_type = mi.UInt32(+mi.BSDFFlags.GlossyReflection)
        bs.sampled_component = mi.UInt32(0)
        ok = active & self._valid(si, wo) & (bs.pdf > 0)
        value = self._f(si.wi, wo) * mi.Frame3f.cos_theta(wo) / dr.maximum(bs.pdf, 1e-20)
        return bs, dr.select(ok, value, 0.0)

    def eval(self, ctx, si, wo, active=True):
        value = self._f(si.wi, wo) * mi.Frame3f.cos_theta(wo)
        return dr.select(active & self._valid(si, wo), value, 0.0)

    def pdf(self, ctx, si, wo, active=True):
        return dr.select(active & self._valid(si, wo), self._pdf(si.wi, wo), 0.0)

    def eval_pdf(self, ctx, si, wo, active=True):
        return self.eval(ctx, si, wo, active), self.pdf(ctx, si, wo, active)

    def traverse(self, callback):
        pass

    def to_string(self):
        return type(self).__name__


class ModifiedPhong(LobeAndCosine):
    """f = kd/pi + ks (s+2)/(2 pi) max(r.wo, 0)^s; the lobe's chance t = avg(ks) / (avg(kd) +
    avg(ks)), 0 for shininess 0 (a flat lobe: cosine sampling covers it)."""

    def __init__(self, props):
        LobeAndCosine.__init__(self, props)
        self.s = props["shininess"]
        self.t = self.ratio if self.s != 0 else 0.0

    def _mirror(self, wi):
        return mi.Vector3f(-wi.x, -wi.y, wi.z)

    def _f(self, wi, wo):
        r = self._mirror(wi)
        lobe = dr.power(dr.maximum(dr.dot(r, wo), 0.0), self.s)
        return self.kd * dr.inv_pi + self.ks * ((self.s + 2) / (2 * math.pi)) * lobe

    def _pdf(self, wi, wo):
        cos_o = mi.Frame3f.cos_theta(wo)
        r = self._mirror(wi)
        lobe = dr.power(dr.maximum(dr.dot(r, wo), 0.0), self.s)
        return (1 - self.t) * dr.maximum(cos_o, 0.0) * dr.inv_pi + self.t * (self.s + 1) / (2 * math.pi) * lobe

    def _lobe(self, wi, sample2):
        # The Phong lobe around r: cos theta = u^(1/(s+1)).
        cos_t = dr.power(sample2.x, 1.0 / (self.s + 1))
        sin_t = dr.safe_sqrt(1 - cos_t * cos_t)
        phi = 2 * math.pi * sample2.y
        return mi.Frame3f(self._mirror(wi)).to_world(mi.Vector3f(sin_t * dr.cos(phi), sin_t * dr.sin(phi), cos_t))


class Ggx(LobeAndCosine):
    """f = kd/pi + F G D / (4 (n.wi)(n.wo)), alpha = roughness, Schlick's F with ks at normal
    incidence; the lobe's chance t = max(0.25, avg(ks) / (avg(kd) + avg(ks))), 0 for roughness
    0 (D has no density). Mitsuba's si.wi is the viewer's direction, wo the light's."""

    def __init__(self, props):
        LobeAndCosine.__init__(self, props)
        self.a = props["roughness"]
        self.t = max(0.25, self.ratio) if self.a != 0 else 0.0

    def _d(self, cos_h):
        a2 = self.a * self.a
        c2 = cos_h * cos_h
        tan2 = dr.maximum(1 - c2, 0.0) / c2
        return a2 / (math.pi * c2 * c2 * dr.square(a2 + tan2))

    def _g1(self, cos_v):
        c2 = cos_v * cos_v
        tan2 = dr.maximum(1 - c2, 0.0) / c2
        return 2 / (1 + dr.sqrt(1 + self.a * self.a * tan2))

    def _f(self, wi, wo):
        h = dr.normalize(wi + wo)
        cos_i, cos_o = mi.Frame3f.cos_theta(wi), mi.Frame3f.cos_theta(wo)
        fresnel = self.ks + (1 - self.ks) * dr.power(1 - dr.dot(wo, h), 5)
        spec = fresnel * self._g1(cos_i) * self._g1(cos_o) * self._d(mi.Frame3f.cos_theta(h)) / (4 * cos_i * cos_o)
        return self.kd * dr.inv_pi + spec

    def _pdf(self, wi, wo):
        h = dr.normalize(wi + wo)
        cos_o = mi.Frame3f.cos_theta(wo)
        cos_h = mi.Frame3f.cos_theta(h)
        lobe = self._d(cos_h) * cos_h / (4 * dr.abs(dr.dot(h, wo)))
        return (1 - self.t) * dr.maximum(cos_o, 0.0) * dr.inv_pi + self.t * lobe

    def _lobe(self, wi, sample2):
        # A half vector from D (theta_h = atan(alpha sqrt(u) / sqrt(1 - u))), wi reflected about it.
        theta = dr.atan(self.a * dr.sqrt(sample2.x) / dr.sqrt(1 - sample2.x))
        phi = 2 * math.pi * sample2.y
        h = mi.Vector3f(dr.sin(theta) * dr.cos(phi), dr.sin(theta) * dr.sin(phi), dr.cos(theta))
        return 2 * dr.dot(wi, h) * h - wi


_registered = False


def _register():
    global _registered
    if not _registered:
        mi.register_bsdf("vkrt_phong", lambda props: ModifiedPhong(props))
        mi.register_bsdf("vkrt_ggx", lambda props: Ggx(props))
        _registered = True


def _rotation(axis, degrees):
    x, y, z = axis
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s, 0],
            [y * x * (1 - c) + z * s, c + y * y * (1 - c), y * z * (1 - c) - x * s, 0],
            [z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c), 0],
            [0, 0, 0, 1]]


def _mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def _apply(m, p):
    return [sum(m[i][k] * (p[k] if k < 3 else 1.0) for k in range(4)) for i in range(3)]


def read_test(path):
    """The scene as plain data: settings, camera, and (material, [triangle]) groups."""
    identity = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    stack = [identity]
    material = {"diffuse": (0, 0, 0), "specular": (0, 0, 0), "shininess": 1.0, "emission": (0, 0, 0),
                "brdf": "phong", "roughness": 0.0}
    scene = {"size": (160, 120), "camera": None, "maxdepth": 5, "spp": 1, "rr": False, "nee": "off",
             "groups": {}, "quads": [], "spheres": [], "gamma": 1.0}
    vertices = []
    for number, raw in enumerate(Path(path).read_text().splitlines(), 1):
        words = raw.split()
        if not words or words[0].startswith("#"):
            continue
        cmd, args = words[0], words[1:]
        num = [float(a) for a in args] if cmd not in ("integrator", "output", "nexteventestimation",
                                                       "russianroulette", "importancesampling", "brdf",
                                                       "lightstratify") else []
        if cmd == "size":
            scene["size"] = (int(num[0]), int(num[1]))
        elif cmd == "camera":
            scene["camera"] = num
        elif cmd == "maxdepth":
            scene["maxdepth"] = int(num[0])
        elif cmd == "spp":
            scene["spp"] = int(num[0])
        elif cmd == "gamma":
            scene["gamma"] = num[0]
        elif cmd == "russianroulette":
            scene["rr"] = args[0] == "on"
        elif cmd == "nexteventestimation":
            scene["nee"] = args[0]
        elif cmd == "vertex":
            vertices.append(num)
        elif cmd == "tri":
            m = stack[-1]
            tri = [_apply(m, vertices[int(i)]) for i in num]
            key = tuple(sorted(material.items()))
            scene["groups"].setdefault(key, []).append(tri)
        elif cmd == "sphere":
            m = _mul(stack[-1], _mul([[1, 0, 0, num[0]], [0, 1, 0, num[1]], [0, 0, 1, num[2]], [0, 0, 0, 1]],
                                     [[num[3], 0, 0, 0], [0, num[3], 0, 0], [0, 0, num[3], 0], [0, 0, 0, 1]]))
            scene["spheres"].append((m, dict(material)))
        elif cmd in ("diffuse", "specular", "emission"):
            material = dict(material, **{cmd: tuple(num)})
        elif cmd == "shininess":
            material = dict(material, shininess=num[0])
        elif cmd == "brdf":
            if args[0] not in ("phong", "ggx"):
                raise ValueError(f"{path}:{number}: brdf {args[0]} is not converted")
            material = dict(material, brdf=args[0])
        elif cmd == "roughness":
            material = dict(material, roughness=num[0])
        elif cmd == "quadLight":
            m = stack[-1]
            a = _apply(m, num[0:3])
            ab = [x - y for x, y in zip(_apply(m, [num[0] + num[3], num[1] + num[4], num[2] + num[5]]), a)]
            ac = [x - y for x, y in zip(_apply(m, [num[0] + num[6], num[1] + num[7], num[2] + num[8]]), a)]
            scene["quads"].append((a, ab, ac, num[9:12]))
        elif cmd == "pushTransform":
            stack.append(stack[-1])
        elif cmd == "popTransform":
            stack.pop()
        elif cmd == "translate":
            t = [[1, 0, 0, num[0]], [0, 1, 0, num[1]], [0, 0, 1, num[2]], [0, 0, 0, 1]]
            stack[-1] = _mul(stack[-1], t)
        elif cmd == "scale":
            s = [[num[0], 0, 0, 0], [0, num[1], 0, 0], [0, 0, num[2], 0], [0, 0, 0, 1]]
            stack[-1] = _mul(stack[-1], s)
        elif cmd == "rotate":
            stack[-1] = _mul(stack[-1], _rotation(num[0:3], num[3]))
        elif cmd in ("ambient", "maxverts", "output", "integrator", "importancesampling", "lightsamples",
                     "lightstratify"):
            pass
        else:
            raise ValueError(f"{path}:{number}: '{cmd}' is not converted to Mitsuba")
    return scene


def load(path, spp=None, sampler="independent"):
    """(scene dict for mi.load_dict, spp). Light paths of at most maxdepth + 1 segments, as
    vkrt's depth rule; Russian roulette only when the scene asks for it. `sampler`: one of
    Mitsuba's ("independent", "stratified", ...)."""
    _register()
    s = read_test(path)
    fx, fy, fz, ax, ay, az, ux, uy, uz, fovy = s["camera"]
    width, height = s["size"]
    depth = s["maxdepth"]
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1 if depth < 0 else depth + 1,
                       "rr_depth": 1 if s["rr"] else 1 << 30, "hide_emitters": False},
        "sensor": {
            "type": "perspective", "fov_axis": "y", "fov": fovy,
            "to_world": mi.ScalarTransform4f().look_at(origin=[fx, fy, fz], target=[ax, ay, az], up=[ux, uy, uz]),
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"},
                     "pixel_format": "rgb"},
            "sampler": {"type": sampler, "sample_count": spp or s["spp"]},
        },
    }
    folder = Path(tempfile.mkdtemp(prefix="vkrt-mitsuba-"))
    for i, (key, tris) in enumerate(s["groups"].items()):
        mat = dict(key)
        d[f"group{i}"] = _mesh(folder / f"group{i}.obj", tris, _bsdf(mat), mat["emission"])
    for i, (m, mat) in enumerate(s["spheres"]):
        d[f"sphere{i}"] = {"type": "sphere", "to_world": mi.ScalarTransform4f(m), "bsdf": _bsdf(mat)}
        if any(e != 0 for e in mat["emission"]):
            d[f"sphere{i}"]["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": list(mat["emission"])}}
    for i, (a, ab, ac, L) in enumerate(s["quads"]):
        p = [a, [a[k] + ab[k] for k in range(3)], [a[k] + ab[k] + ac[k] for k in range(3)],
             [a[k] + ac[k] for k in range(3)]]
        # Wound so that the face normal is cross(ac, ab): (a, a+ac, a+ab+ac), (a, a+ab+ac, a+ab).
        tris = [[p[0], p[3], p[2]], [p[0], p[2], p[1]]]
        black = {"type": "diffuse", "reflectance": {"type": "rgb", "value": [0, 0, 0]}}
        d[f"quad{i}"] = _mesh(folder / f"quad{i}.obj", tris, black, tuple(L))
    return d, spp or s["spp"]


def _bsdf(mat):
    kd, ks = mat["diffuse"], mat["specular"]
    d = {"kd_r": kd[0], "kd_g": kd[1], "kd_b": kd[2], "ks_r": ks[0], "ks_g": ks[1], "ks_b": ks[2]}
    if mat["brdf"] == "ggx":
        return dict(d, type="vkrt_ggx", roughness=mat["roughness"])
    return dict(d, type="vkrt_phong", shininess=mat["shininess"])


def _mesh(path, tris, bsdf, emission):
    """The triangles as an OBJ file (face normals from the winding) with their BSDF and emitter."""
    lines = [f"v {p[0]!r} {p[1]!r} {p[2]!r}" for tri in tris for p in tri]
    lines += [f"f {3 * i + 1} {3 * i + 2} {3 * i + 3}" for i in range(len(tris))]
    path.write_text("\n".join(lines) + "\n")
    out = {"type": "obj", "filename": str(path), "face_normals": True, "bsdf": bsdf}
    if any(e != 0 for e in emission):
        out["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": list(emission)}}
    return out


def write_pfm(path, rgb):
    """rgb: rows top to bottom of [r, g, b] floats (a numpy array H x W x 3)."""
    import numpy as np
    a = np.asarray(rgb, dtype="<f4")[::-1]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (a.shape[1], a.shape[0]))
        f.write(a.tobytes())


def main():
    """bench/mitsuba_scene.py SCENE --spp 1,4,16 --out DIR: renders SCENE with Mitsuba 3
    (llvm_ad_rgb) at each sample count, writes DIR/spp-N.pfm and DIR/times.json (seconds per
    render, the first one including Mitsuba's kernel compilation)."""
    import argparse
    import json
    import time
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("--spp", default="1,4,16,64")
    ap.add_argument("--out", required=True)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--sampler", default="independent", help="Mitsuba's sampler: independent, stratified, ...")
    args = ap.parse_args()
    mi.set_variant("llvm_ad_rgb")
    if args.threads:
        dr.set_thread_count(args.threads)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    scene_dict, _ = load(args.scene, sampler=args.sampler)
    scene = mi.load_dict(scene_dict)
    times = {"load": time.perf_counter() - t0, "renders": []}
    t0 = time.perf_counter()
    mi.render(scene, spp=1, seed=1000).numpy()   # the first render compiles Mitsuba's kernels
    times["first_render_1spp"] = time.perf_counter() - t0
    for i, n in enumerate(int(x) for x in args.spp.split(",")):
        t0 = time.perf_counter()
        img = mi.render(scene, spp=n, seed=i)
        a = img.numpy()
        seconds = time.perf_counter() - t0
        write_pfm(out / f"spp-{n}.pfm", a)
        times["renders"].append({"spp": n, "seconds": seconds, "file": f"spp-{n}.pfm"})
    (out / "times.json").write_text(json.dumps(times, indent=1))


if __name__ == "__main__":
    main()
