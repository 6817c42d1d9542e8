/// @file egl_context.cpp
#include "render/egl_context.h"

#include "render/context_support.h"
#include "render/gl_api.h"
#include "render/render_error.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>

namespace impulse2d::render {

namespace {

std::string describe_request(int width, int height) {
  return context_support::describe_request("EGL on Mesa's surfaceless platform", width, height);
}

std::string egl_error() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

bool has_extension(const char* extensions, const char* name) {
  if (extensions == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = std::strstr(extensions, name); at != nullptr;
       at = std::strstr(at + length, name)) {
    const bool starts = at == extensions || at[-1] == ' ';
    const bool ends = at[length] == ' ' || at[length] == '\0';
    if (starts && ends) return true;
  }
  return false;
}

}  // namespace

EglContext::EglContext(int width, int height) : OffscreenContext(width, height) {
  const std::string request = describe_request(width, height);
  context_support::check_size(request, width, height);
  const auto fail = [&](const std::string& what) {
    release();
    throw RenderError("cannot create offscreen context (" + request + "): " + what);
  };
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS),
                     "EGL_MESA_platform_surfaceless")) {
    fail("this EGL has no EGL_MESA_platform_surfaceless (Debian: apt-get install libegl-mesa0)");
  }
  const auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_platform_display == nullptr) fail("eglGetPlatformDisplayEXT is missing");
  display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT failed: " + egl_error());
  if (!eglInitialize(display_, nullptr, nullptr)) {
    display_ = nullptr;  // nothing to terminate
    fail("eglInitialize failed: " + egl_error());
  }
  const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
  for (const char* needed : {"EGL_KHR_no_config_context", "EGL_KHR_surfaceless_context"}) {
    if (!has_extension(extensions, needed)) fail(std::string("the display lacks ") + needed);
  }
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed: " + egl_error());
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               context_support::requested_major,
                               EGL_CONTEXT_MINOR_VERSION,
                               context_support::requested_minor,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context_ == EGL_NO_CONTEXT) {
    context_ = nullptr;
    fail("eglCreateContext failed: " + egl_error() +
         "; the driver may not support that GL version (llvmpipe does)");
  }
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    fail("eglMakeCurrent failed: " + egl_error());
  }
  read_gl_strings();
  try {
    context_support::check_viewport_limit(request, renderer(), width, height);
  } catch (const RenderError&) {
    release();
    throw;
  }
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &renderbuffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(status));
    fail(std::string("the RGBA8 framebuffer object is incomplete (status ") + code + ")");
  }
  glViewport(0, 0, width, height);
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
}

EglContext::~EglContext() { release(); }

void EglContext::release() {
  if (display_ == nullptr) return;
  if (context_ != nullptr) {
    if (eglGetCurrentContext() == context_) {
      if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
      if (renderbuffer_ != 0) glDeleteRenderbuffers(1, &renderbuffer_);
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(display_, context_);
    context_ = nullptr;
  }
  // The surfaceless display is shared by every context of the process: eglTerminate would
  // pull it from under other live contexts, so it stays initialised (Mesa reference-counts
  // nothing here; the process exit releases it).
  display_ = nullptr;
}

void EglContext::make_current() {
  if (eglGetCurrentContext() == context_) return;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw RenderError("eglMakeCurrent failed for the " + std::to_string(width()) + "x" +
                      std::to_string(height()) + " EGL context: " + egl_error());
  }
}

void EglContext::read_pixels(Frame& frame) {
  make_current();
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width(), height(), GL_RGBA, GL_UNSIGNED_BYTE, buffer_.data());
  context_support::copy_bottom_up(buffer_.data(), width(), height(), frame);
}

}  // namespace impulse2d::render
