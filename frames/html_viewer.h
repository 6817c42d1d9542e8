#pragma once
/// @file html_viewer.h
/// A self-contained HTML page that plays a frame sequence in the browser, written beside the
/// frames as `<scene>.html` by `impulse2d render --html`: a scrubber, play/pause, the step,
/// time, energy and contacts of each frame, a clickable timeline of energy and contacts (and,
/// with the events overlay, a mark per frame with events: touch, hit, sensor rows), and
/// keyboard stepping, and a switch between pre-rendered overlay variants. The page loads the
/// PNG frames by relative path, embeds the per-frame data as JSON and uses no network
/// resources; `#frame=N` in its URL opens frame N, `#frame=N&overlays=NAME` with a variant.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frames/frame_index.h"
#include "render/event_marks.h"

namespace impulse2d::demos {

/// One frame as the viewer shows it.
struct ViewerFrame {
  FrameIndexRow index;        ///< number, step, simulated time (s), file name
  double energy = 0.0;        ///< total mechanical energy when drawn, J (see `mechanical_energy`)
  std::int64_t contacts = 0;  ///< touching pairs when drawn (see `contact_count`)
  /// The events of the steps since the frame before (what the events overlay draws).
  render::EventCounts events;
};

/// One set of frames the page can switch to (see overlay_variants.h).
struct ViewerVariant {
  std::string label;      ///< what the switch says, e.g. "none" or "normals"
  std::string directory;  ///< relative to the page, e.g. "tutorial.overlays/none"; "" beside it
};

/// What the page shows besides the frames.
struct ViewerPage {
  std::string title;                ///< scene name and caption
  std::string details;              ///< one line: parameters, overlays, frame size
  int width = 800;                  ///< frame width, pixels
  int height = 600;                 ///< frame height, pixels
  std::vector<ViewerFrame> frames;  ///< in frame order
  /// The run draws the events overlay: the readout and the timeline show each frame's events.
  bool events = false;
  /// The overlay switch, the frames beside the page first; the same file names in each
  /// directory. Empty or one entry: no switch.
  std::vector<ViewerVariant> variants;
};

/// `directory/<scene>.html` (named by scene so that several scenes can share a directory).
std::filesystem::path html_viewer_path(const std::filesystem::path& directory,
                                       const std::string& scene);

/// The page's HTML text.
std::string html_viewer_page(const ViewerPage& page);

/// Writes `html_viewer_page(page)` to `path` (temporary file + rename). Throws
/// `render::RenderError` naming the path when it cannot be written.
void write_html_viewer(const std::filesystem::path& path, const ViewerPage& page);

}  // namespace impulse2d::demos
