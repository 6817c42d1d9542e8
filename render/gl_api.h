#pragma once
/// @file gl_api.h
/// The OpenGL declarations render/ uses. libOSMesa exports every entry point, so the
/// prototypes are declared directly (no loader). Internal to render/: public headers never
/// include it, so callers do not see GL.

#ifndef GL_GLEXT_PROTOTYPES
/// Asks <GL/glext.h> for the prototypes of every entry point (no loader).
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
