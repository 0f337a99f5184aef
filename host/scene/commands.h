// The commands of the scene format (doc/scene-format.md, "Commands"; doc/path-tracing.md,
// "Commands") and their names, but for the shapes' own (shapes/shape_list.h,
// VKRT_SHAPE_COMMANDS), which the parser looks up after these.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace vkrt {

// kCommandNames spells them as the format does, in this order, which is also the order of
// lookup: the commands of big meshes first.
enum class Command {
  Vertex, Tri, VertexNormal, TriNormal, Size, MaxDepth, Output, Camera, MaxVerts, MaxVertNorms,
  Translate, Rotate, Scale, PushTransform, PopTransform, Directional, Point, Attenuation, Ambient, Diffuse,
  Specular, Emission, Shininess,
  // doc/path-tracing.md, "Commands"
  Integrator, QuadLight, LightSamples, LightStratify, Spp, NextEventEstimation, RussianRoulette,
  ImportanceSampling, Brdf, Roughness, Gamma, Count
};
inline constexpr std::string_view kCommandNames[] = {
    "vertex", "tri", "vertexnormal", "trinormal", "size", "maxdepth", "output", "camera", "maxverts",
    "maxvertnorms", "translate", "rotate", "scale", "pushTransform", "popTransform", "directional", "point",
    "attenuation", "ambient", "diffuse", "specular", "emission", "shininess", "integrator", "quadLight",
    "lightsamples", "lightstratify", "spp", "nexteventestimation", "russianroulette", "importancesampling", "brdf",
    "roughness", "gamma"};
static_assert(std::size(kCommandNames) == static_cast<std::size_t>(Command::Count));

constexpr std::string_view nameOf(Command c) { return kCommandNames[static_cast<std::size_t>(c)]; }

// The index in `names` of the name spelled `name`.
std::optional<std::size_t> indexNamed(std::span<const std::string_view> names, std::string_view name);

// `maxDepth`, `pushtransform`: the index in `names` of a name in another case (no two commands
// differ only in case).
std::optional<std::size_t> indexNamedIgnoringCase(std::span<const std::string_view> names, std::string_view name);

}  // namespace vkrt
