/// @file offscreen_context.cpp
#include "render/offscreen_context.h"

#include "render/gl_api.h"

namespace impulse2d::render {

namespace {

// glGetString(name) of the current context, "?" when it has none.
std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text != nullptr ? std::string(reinterpret_cast<const char*>(text)) : std::string("?");
}

}  // namespace

void OffscreenContext::read_gl_strings() {
  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);
}

}  // namespace impulse2d::render
