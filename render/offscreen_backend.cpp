/// @file offscreen_backend.cpp
#include "render/offscreen_backend.h"

#include "render/egl_context.h"
#include "render/offscreen_context.h"
#include "render/render_error.h"
#ifndef IMPULSE2D_NO_OSMESA
#include "render/osmesa_context.h"
#endif

#include <atomic>
#include <cstdlib>

namespace impulse2d::render {

namespace {

constexpr const char* kEnvironmentVariable = "IMPULSE2D_BACKEND";

// -1: none set; else the Backend's value.
std::atomic<int> chosen_backend{-1};

}  // namespace

const char* backend_name(Backend backend) {
  return backend == Backend::Egl ? "egl" : "osmesa";
}

Backend parse_backend(const std::string& name, const std::string& where) {
  if (name == "osmesa") return Backend::OSMesa;
  if (name == "egl") return Backend::Egl;
  throw RenderError(where + ": unknown renderer backend '" + name + "' (use osmesa or egl)");
}

bool backend_available(Backend backend) {
#ifdef IMPULSE2D_NO_OSMESA
  return backend == Backend::Egl;
#else
  return backend == Backend::Egl || backend == Backend::OSMesa;
#endif
}

Backend default_backend() {
  const int chosen = chosen_backend.load();
  if (chosen >= 0) return static_cast<Backend>(chosen);
  const char* value = std::getenv(kEnvironmentVariable);
  if (value == nullptr || value[0] == '\0') {
    return backend_available(Backend::OSMesa) ? Backend::OSMesa : Backend::Egl;
  }
  return parse_backend(value, std::string("environment variable ") + kEnvironmentVariable);
}

void set_default_backend(Backend backend) { chosen_backend.store(static_cast<int>(backend)); }

std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height, Backend backend) {
  if (backend == Backend::Egl) return std::make_unique<EglContext>(width, height);
#ifdef IMPULSE2D_NO_OSMESA
  throw RenderError("cannot create offscreen context (OSMesa, " + std::to_string(width) + "x" +
                    std::to_string(height) + "): this build has no OSMesa backend (configured "
                    "with IMPULSE2D_OSMESA=OFF); use the egl backend");
#else
  return std::make_unique<OsmesaContext>(width, height);
#endif
}

std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height) {
  return create_offscreen_context(width, height, default_backend());
}

}  // namespace impulse2d::render
