#pragma once
// The fixed parts of the replay report's page (ReplayReport.h): its style sheet and its script.

namespace rmfx {

// The CSS of index.html.
const char* replayReportStyle();

// The JavaScript at the end of index.html. It decodes the RGBE images that the per-case scripts
// put in `rmfxImages` (id → data: URI), paints every <canvas data-hdr="id"> with the exposure
// (#ev, in stops) and tone mapping (#op: clip or reinhard) chosen, then sRGB-encoded; keeps both in
// the page's address (#ev=1.5&op=reinhard) so a view can be shared; and switches each compare
// between side by side, slider and flicker. What it painted is written into the page for tests
// and curious people: each canvas's data-state ("shown") and data-mean (the mean of its 8-bit RGB
// values), and <body data-painted="N"> once all N canvases are painted.
const char* replayReportScript();

}  // namespace rmfx
