// The band driver of every GPU rendering technique.
#include "gpu/technique_bands.h"

#include <chrono>

#include "gpu/band_buffers.h"
#include "gpu/compute_pipeline.h"
#include "gpu/shader_variant.h"
#include "util/errors.h"
#include "util/timing.h"
#include "all_techniques.comp.h"   // kTechniqueSpirv: every shaders/*.comp, compiled at build time

namespace vkrt {

const TechniqueSpirv& techniqueSpirv(std::string_view name) {
  for (const TechniqueSpirv& row : kTechniqueSpirv)
    if (name == row.name) return row;
  throw InternalError("no shader shaders/" + std::string(name) + ".comp");
}

void prepareTechnique(const Context& context, const TechniqueShader& shader, SceneArrays arrays,
                      std::uint32_t pushBytes) {
  ComputePipeline::prepare(context, shader.words, shader.bytes, ShaderBindings(arrays, shader.texelReads).types,
                           shader.spec, pushBytes);
}

RadianceImage renderTechniqueBands(const Context& context, const SceneUpload& upload, const TechniqueShader& shader,
                                   const TechniqueBatch& batch, RayCounts* rays, VulkanTimings* timings,
                                   VulkanTimings t) {
  const BandLayout& layout = batch.layout;
  auto t0 = std::chrono::steady_clock::now();
  BandBuffers band(context, layout, layout.invocations() * batch.stateBytes, batch.params, batch.stepBudget,
                   batch.firstDispatchSteps, batch.timedBands);
  t.uploadSeconds += secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  t.testedAll = shader.testAll;
  t.texelReads = shader.texelReads;
  t.general = shader.general;
  t.estimatedRays = shader.estimatedRays;
  t.leftOut = shader.leftOut;
  ShaderBindings bindings(batch.arrays, shader.texelReads);
  upload.bind(bindings);
  band.bind(bindings);
  if (batch.bindOwn) batch.bindOwn(bindings);
  ComputePipeline pipeline(context, shader.words, shader.bytes, bindings.types, shader.spec, batch.push.bytes);
  bindings.bindTo(pipeline);
  t.pipelineSeconds += secondsSince(t0);

  // The whole image, or (streaming to batch.rows) one band's rows at a time.
  const int width = static_cast<int>(layout.width);
  RadianceImage image = batch.rows ? RadianceImage() : RadianceImage(width, static_cast<int>(layout.height));
  image.samples = batch.imageSamples;
  RadianceImage rowsImage;
  rowsImage.samples = batch.imageSamples;
  BandHooks hooks{batch.stop, batch.progress,
                  [&](std::uint32_t y0, std::uint32_t rows) {
                    if (!batch.rows) return band.readRows(rows, batch.readScale, image, static_cast<int>(y0));
                    if (rowsImage.height != static_cast<int>(rows)) rowsImage = RadianceImage(width, static_cast<int>(rows));
                    band.readRows(rows, batch.readScale, rowsImage, 0);
                  },
                  {}};
  if (batch.rows) hooks.after = [&](std::uint32_t y0, std::uint32_t) { batch.rows(static_cast<int>(y0), rowsImage); };
  RayCounts counted;
  if (!band.run(pipeline, batch.push.data, *batch.push.bandY0, *batch.push.resume, layout, batch.samples, hooks, t,
                counted))
    return image;
  if (!t.general) recordVariantCompiled(shader.specializedKey);
  if (rays) *rays = counted;
  if (timings) *timings = t;
  return image;
}

}  // namespace vkrt
