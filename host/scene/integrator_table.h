// The integrator table (doc/path-tracing.md, "Integrators" and "Commands"): the integrators,
// each one's keyword and the settings commands it uses, said once, here. The parser reads `integrator`
// by these keywords; finish_scene.cpp derives from the rows the warning for each setting that
// the scene's integrator does not use (the setting then keeps its default).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "gpu_types.h"
#include "scene/commands.h"

namespace vkrt {

// The algorithm (`integrator`). Each value is the id the path shader knows it by (gpu_path.h),
// so that the GPU parameters take it as it is; the values count 0, 1, ... (kIntegratorCount).
enum class Integrator : std::uint32_t {
  Raytracer = gpu::kIntegratorRaytracer,
  AnalyticDirect = gpu::kIntegratorAnalyticDirect,
  Direct = gpu::kIntegratorDirect,
  PathTracer = gpu::kIntegratorPathTracer,
};

// A set of commands: a bit per Command.
using CommandSet = std::uint64_t;
static_assert(static_cast<std::size_t>(Command::Count) <= 64);

constexpr CommandSet commandSet(std::initializer_list<Command> commands) {
  CommandSet set = 0;
  for (Command c : commands) set |= CommandSet{1} << static_cast<unsigned>(c);
  return set;
}
constexpr bool contains(CommandSet set, Command c) { return (set >> static_cast<unsigned>(c)) & 1u; }

struct IntegratorRow {
  std::string_view name;   // its keyword: `integrator NAME`
  CommandSet uses = 0;     // the settings commands it uses
};

// The table, a row per integrator. A switch with no default: a new Integrator does not
// compile (-Wswitch) until it has its row. `maxdepth` is no setting here: the Whitted model
// and the path tracer read it, and analyticdirect and direct, which need none, take it
// without a warning.
constexpr IntegratorRow integratorRow(Integrator i) {
  using C = Command;
  switch (i) {
    case Integrator::Raytracer:   // the Whitted model: none of them
      return {"raytracer", 0};
    case Integrator::AnalyticDirect:   // exact and diffuse: no light samples and no BRDF
      return {"analyticdirect", commandSet({C::QuadLight, C::Spp, C::Gamma})};
    case Integrator::Direct:   // follows no paths
      return {"direct", commandSet({C::QuadLight, C::Spp, C::Gamma, C::LightSamples, C::LightStratify, C::Brdf,
                                    C::Roughness})};
    case Integrator::PathTracer:
      return {"pathtracer", commandSet({C::QuadLight, C::Spp, C::Gamma, C::LightSamples, C::LightStratify, C::Brdf,
                                        C::Roughness, C::NextEventEstimation, C::RussianRoulette,
                                        C::ImportanceSampling})};
  }
  return {};   // not an Integrator
}

// How many integrators there are: the enum's values 0, 1, ... that have a row.
inline constexpr std::size_t kIntegratorCount = [] {
  std::size_t n = 0;
  while (!integratorRow(static_cast<Integrator>(n)).name.empty()) ++n;
  return n;
}();

constexpr Integrator integratorAt(std::size_t index) { return static_cast<Integrator>(index); }
constexpr std::string_view nameOf(Integrator i) { return integratorRow(i).name; }

// The keywords of `integrator`, in the order of the enum.
inline constexpr std::array<std::string_view, kIntegratorCount> kIntegratorNames = [] {
  std::array<std::string_view, kIntegratorCount> names{};
  for (std::size_t i = 0; i < kIntegratorCount; ++i) names[i] = nameOf(integratorAt(i));
  return names;
}();

// The settings commands: those some integrator uses (the commands of doc/path-tracing.md,
// "Commands" but `integrator` and `maxdepth`). Every other command is read under every
// integrator without a warning.
inline constexpr CommandSet kIntegratorSettings = [] {
  CommandSet set = 0;
  for (std::size_t i = 0; i < kIntegratorCount; ++i) set |= integratorRow(integratorAt(i)).uses;
  return set;
}();

}  // namespace vkrt
