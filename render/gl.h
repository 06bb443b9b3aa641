#pragma once
// The OpenGL 3.3 core API for render/ code. libOSMesa exports every gl*
// entry point (verified with `nm -D libOSMesa.so.8`), so the prototypes are
// called directly instead of being loaded through OSMesaGetProcAddress.
// The EGL backend's contexts are reached through the same entry points
// (docs/decisions/012-egl-backend.md). glcorearb.h cannot be mixed with
// GL/gl.h, which GL/osmesa.h pulls in; only render/osmesa_context.cpp includes
// the latter and it never includes this file.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
