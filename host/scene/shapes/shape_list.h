// The shapes, listed once. Every place on the host that lists the kinds of shape expands
// these lists: the scene's arrays and the GPU's, the dispatch by primitive reference
// (shape.h), the ray offsets, the buffers and their bindings, the parser's shape commands.
// A new shape is its files (shapes/<shape>.{h,cpp}, shaders/shapes/<shape>.glsl), its rows
// here, its layout, kind and binding in gpu_scene.h, and its lines in shaders/intersect.glsl
// (doc/design.md, "What a change touches").
#pragma once

#include "gpu_types.h"
#include "scene/shapes/sphere.h"
#include "scene/shapes/triangle.h"

// X(Type, member, name, kind, GpuType, binding): one row per kind of shape, in the order of
// their kinds (0, 1, ...; shape.h checks it). Type: the host's (double, world space). member:
// the SceneDesc and GpuScene array of them, also their plural in messages. name: the
// singular. kind: gpu_scene.h's (primRef). GpuType: the GPU layout, of which flatten() makes
// one per shape by the shape's toGpu. binding: where both shaders read that array.
// Expanded inside namespace vkrt.
#define VKRT_SHAPES(X)                                                                              \
  X(Triangle, triangles, "triangle", gpu::kPrimTriangle, gpu::GpuTriangle, gpu::kBindingTriangles) \
  X(Sphere, spheres, "sphere", gpu::kPrimSphere, gpu::GpuSphere, gpu::kBindingSpheres)

// X(name, read, member): the scene format's commands that make one shape each. name: the
// command; read: its reader, which takes a ShapeCommand (shape_command.h) and gives the shape
// or nothing (after an error); member: the SceneDesc array the shape joins. The triangles'
// commands are the parser's own: they read its vertex lists.
#define VKRT_SHAPE_COMMANDS(X) X("sphere", shapes::readSphere, spheres)
