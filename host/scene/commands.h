// The commands of the scene format (doc/scene-format.md, "Commands"; doc/path-tracing.md,
// "Commands") and their names.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace vkrt {

// kCommandNames spells them as the format does, in this order, which is also the order of
// lookup: the commands of big meshes first.
enum class Command {
  Vertex, Tri, VertexNormal, TriNormal, Size, MaxDepth, Output, Camera, Sphere, MaxVerts, MaxVertNorms,
  Translate, Rotate, Scale, PushTransform, PopTransform, Directional, Point, Attenuation, Ambient, Diffuse,
  Specular, Emission, Shininess,
  // doc/path-tracing.md, "Commands"
  Integrator, QuadLight, LightSamples, LightStratify, Spp, NextEventEstimation, RussianRoulette,
  ImportanceSampling, Brdf, Roughness, Gamma, Count
};
inline constexpr std::string_view kCommandNames[] = {
    "vertex", "tri", "vertexnormal", "trinormal", "size", "maxdepth", "output", "camera", "sphere", "maxverts",
    "maxvertnorms", "translate", "rotate", "scale", "pushTransform", "popTransform", "directional", "point",
    "attenuation", "ambient", "diffuse", "specular", "emission", "shininess", "integrator", "quadLight",
    "lightsamples", "lightstratify", "spp", "nexteventestimation", "russianroulette", "importancesampling", "brdf",
    "roughness", "gamma"};
static_assert(std::size(kCommandNames) == static_cast<std::size_t>(Command::Count));

constexpr std::string_view nameOf(Command c) { return kCommandNames[static_cast<std::size_t>(c)]; }

// The command spelled `name`.
std::optional<Command> commandNamed(std::string_view name);

// `maxDepth`, `pushtransform`: a command in another case (no two commands differ only in case).
std::optional<Command> commandNamedIgnoringCase(std::string_view name);

}  // namespace vkrt
