// What a render reports on stderr: --stats, its samples, its NaN pixels; and --compare's JSON
// figures (host/cli/render_report.h).
#include "cli/render_report.h"

#include <cstdio>

#include "util/counted.h"
#include "util/json.h"

namespace vkrt {

// " (N samples)" after a path integrator's output, with "time up" when --time ended it, and
// how far past it the first batch ran when that alone took longer.
std::string samplesNote(const RenderReport& r) {
  if (!r.pathIntegrator) return "";
  std::string past;
  if (r.firstBatchPastLimit > 0) {   // (under --time the first batch is one sample)
    char s[32];
    std::snprintf(s, sizeof s, r.firstBatchPastLimit >= 1 ? "%.1f" : "%.2g", r.firstBatchPastLimit);
    past = std::string("; the first sample per pixel, which every render takes, ended ") + s + " s past --time";
  }
  return ", " + counted(r.samples, "sample", "samples") + " per pixel" +
         (r.timeUp ? " when the time was up" : "") + past;
}

// "3 lights (1 point, 2 quad)": the total, then each kind there is.
static std::string lightsText(const RenderReport::Lights& l) {
  std::string kinds;
  auto add = [&](std::size_t n, const std::string& kind) {
    if (n > 0) kinds += (kinds.empty() ? "" : ", ") + kind;
  };
  for (std::size_t type = 0; type < kLightTypeCount; ++type)
    add(l.byType[type], std::to_string(l.byType[type]) + " " + std::string(kLightTypeNames[type]));
  add(l.quad, std::to_string(l.quad) + " quad");
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind)
    add(l.emissive[kind], counted(l.emissive[kind], "emissive " + std::string(shapes::kNames[kind]),
                                        "emissive " + std::string(shapes::kPluralNames[kind])));
  return counted(l.total(), "light", "lights") + (kinds.empty() ? "" : " (" + kinds + ")");
}

void printStats(const RenderRequest& req, const RenderReport& r) {
  const double ms = 1e3;
  std::string primitives;   // "2 triangles, 1 sphere, ": every kind of shape
  for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind) {
    using shapes::kNames, shapes::kPluralNames;
    primitives += counted(r.primitives[kind], kNames[kind], kPluralNames[kind]) + ", ";
  }
  std::fprintf(stderr, "vkrt: %s %dx%d maxdepth %d: %s%s; backend %s", req.scenePath.c_str(), r.width, r.height,
               r.maxDepth, primitives.c_str(), lightsText(r.lights).c_str(), r.backend.c_str());
  if (req.backend == Backend::Cpu)
    std::fprintf(stderr, ", %s", counted(r.threads, "thread", "threads").c_str());
  if (!r.estimator.empty()) std::fprintf(stderr, "\n  estimator: %s", r.estimator.c_str());
  std::fprintf(stderr, "\n  parse   %9.1f ms\n", r.parseSeconds * ms);
  std::fprintf(stderr, "  build   %9.1f ms  (BVH, %s", r.buildSeconds * ms,
               counted(r.bvhNodes, "node", "nodes").c_str());
  if (req.backend == Backend::Vulkan)
    std::fprintf(stderr, "; beside it the first batch's pipeline, %.1f ms", r.pipelineAheadSeconds * ms);
  std::fprintf(stderr, ")\n");
  std::fprintf(stderr, "  render  %9.1f ms\n", r.renderSeconds * ms);
  if (req.backend == Backend::Vulkan) {
    const VulkanTimings& v = r.vulkan;
    std::fprintf(stderr, "    instance  %9.1f ms\n", r.instanceSeconds * ms);
    std::fprintf(stderr, "    device    %9.1f ms\n", r.deviceSeconds * ms);
    std::fprintf(stderr, "    upload    %9.1f ms\n", v.uploadSeconds * ms);
    std::fprintf(stderr, "    pipeline  %9.1f ms  (%s reads)\n", v.pipelineSeconds * ms,
                 v.texelReads ? "texel-buffer" : "storage-buffer");
    std::fprintf(stderr, "    first dispatch (with JIT) %9.1f ms\n", v.firstDispatchSeconds * ms);
    std::fprintf(stderr, "    shader: the %s variant (about %.3g M rays; %s)\n",
                 v.general ? "general" : "specialised", v.estimatedRays / 1e6,
                 v.testedAll ? "each ray tests every primitive" : "rays walk the BVH");
    std::fprintf(stderr, "    left out: %s\n", v.leftOut.empty() ? "nothing" : v.leftOut.c_str());
    std::fprintf(stderr, "    dispatch  %9.1f ms  (%s, %s, %s)\n", v.dispatchSeconds * ms,
                 counted(v.bands, "band", "bands").c_str(),
                 counted(v.dispatches, "dispatch", "dispatches").c_str(),
                 counted(v.suspensions, "suspension", "suspensions").c_str());
    std::fprintf(stderr, "    readback  %9.1f ms\n", v.readbackSeconds * ms);
  }
  std::fprintf(stderr, "  write   %9.1f ms\n", r.writeSeconds * ms);
  double mrays = r.renderSeconds > 0 ? static_cast<double>(r.rays.total()) / r.renderSeconds / 1e6 : 0.0;
  std::fprintf(stderr, "  rays    %llu = primary %llu + shadow %llu + secondary %llu; %.1f Mrays/s\n",
               static_cast<unsigned long long>(r.rays.total()), static_cast<unsigned long long>(r.rays.primary),
               static_cast<unsigned long long>(r.rays.shadow), static_cast<unsigned long long>(r.rays.secondary),
               mrays);
  // The Vulkan backend's BVH walk, per ray traced (bench/: how a tree or a traversal compares).
  if (r.rays.total() > 0 && r.rays.boxTests + r.rays.primitiveTests > 0) {
    const double rays = static_cast<double>(r.rays.total());
    std::fprintf(stderr, "  walk    %.2f box tests and %.2f primitive tests a ray\n",
                 static_cast<double>(r.rays.boxTests) / rays, static_cast<double>(r.rays.primitiveTests) / rays);
  }
}

std::string reportJson(const RenderReport& r) {
  char buf[1024];
  const VulkanTimings& v = r.vulkan;
  std::snprintf(buf, sizeof buf,
                "{\"backend\":%s,\"seconds\":%.6f,\"parse_s\":%.6f,\"build_s\":%.6f,\"render_s\":%.6f,"
                "\"instance_s\":%.6f,\"device_s\":%.6f,\"upload_s\":%.6f,\"pipeline_ahead_s\":%.6f,\"pipeline_s\":%.6f,"
                "\"first_dispatch_s\":%.6f,\"dispatch_s\":%.6f,\"readback_s\":%.6f,\"rays\":%llu,"
                "\"shadow_rays\":%llu,\"secondary_rays\":%llu,\"box_tests\":%llu,\"primitive_tests\":%llu}",
                jsonQuoted(r.backend).c_str(), r.parseSeconds + r.buildSeconds + r.renderSeconds, r.parseSeconds, r.buildSeconds,
                r.renderSeconds, r.instanceSeconds, r.deviceSeconds, v.uploadSeconds, r.pipelineAheadSeconds, v.pipelineSeconds,
                v.firstDispatchSeconds, v.dispatchSeconds, v.readbackSeconds,
                static_cast<unsigned long long>(r.rays.total()), static_cast<unsigned long long>(r.rays.shadow),
                static_cast<unsigned long long>(r.rays.secondary), static_cast<unsigned long long>(r.rays.boxTests),
                static_cast<unsigned long long>(r.rays.primitiveTests));
  return buf;
}

// The warning for pixels whose colour was NaN or infinite (with --strict: an error already);
// under --compare, which writes nothing, named by the backend that rendered them.
void warnNonFinite(bool quiet, const RenderReport& report, const std::string& backend) {
  if (report.rays.nonFinite > 0 && !quiet)
    std::fprintf(stderr, "vkrt: warning: %s%s a NaN or infinite colour (%s); the scene has extreme values\n",
                 backend.empty() ? "" : (backend + ": ").c_str(),
                 counted(report.rays.nonFinite, "pixel had", "pixels had").c_str(),
                 backend.empty() ? "NaN written as 0, +infinity as 255 in PNG and PPM, as the largest float in PFM and EXR"
                                 : "compared as 8-bit: NaN as 0, +infinity as 255");
}

}  // namespace vkrt
