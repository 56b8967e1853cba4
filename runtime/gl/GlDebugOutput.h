#pragma once
// The driver's own words about a GL error: with RMFX_GL_DEBUG set (to anything but 0) in the
// environment, headless contexts are created as debug contexts and every message of the driver's
// debug output (KHR_debug) of medium or high severity, and every error, is written to stderr as
// "rmfx: GL debug: …". rmfx's own error messages say which pass a GL error happened in; this says
// which call and why, in the words of the driver that raised it (NVIDIA's are specific).

namespace rmfx {

bool glDebugOutputAsked();          // RMFX_GL_DEBUG is set and not "0"
void installGlDebugOutput();        // on the current context; needs GL 4.3 or KHR_debug

}  // namespace rmfx
