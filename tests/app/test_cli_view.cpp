// The view options of `render` and `sheet` run as a subprocess: every one changes the frame
// (or leaves it as the default when it names the default), bad values are bad usage (exit 2)
// with a message naming the option, and a scene file's "view" block does what the options do.
#include <functional>
#include <string>

#include "tests/support/cli_test_support.h"

namespace {

using cli_test::read_file;
using cli_test::Result;
namespace fs = std::filesystem;

// Two named balls on a named ground: names for --follow and --highlight, contacts for overlays.
// The accumulated solver leaves the left ball's 2 cm start overlap a few mm deep at step 30,
// where the penetration overlay can show it (the default soft step has pushed it out by then).
const char* const named_scene = R"({
  "name": "named",
  "settings": {"solver": "accumulated"},
  "bodies": [
    {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [6, 0.5]}, "position": [0, -0.5]},
    {"name": "left", "shape": {"type": "circle", "radius": 0.5}, "position": [-2, 0.48]},
    {"name": "right", "shape": {"type": "circle", "radius": 0.5}, "position": [2, 3]}
  ],
  "run": {"steps": 40, "frames": "30:30"},
  "overlays": ["points", "normals", "normal_impulses", "penetration", "ids"]
})";

/// The PNG `png` without its tEXt chunks (the metadata names the scene file, which differs
/// between two files drawing the same frame): what is left is the image.
std::string without_text_chunks(const std::string& png) {
  std::string image = png.substr(0, 8);  // the signature
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const auto byte = [&](std::size_t i) { return static_cast<std::size_t>(static_cast<unsigned char>(png[i])); };
    const std::size_t length = (byte(at) << 24) | (byte(at + 1) << 16) | (byte(at + 2) << 8) | byte(at + 3);
    const std::size_t chunk = length + 12;  // length, type, data, CRC
    if (png.compare(at + 4, 4, "tEXt") != 0) image += png.substr(at, chunk);
    at += chunk;
  }
  return image;
}

class CliViewTest : public cli_test::CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream(dir_ / "named.json") << named_scene;
  }

  /// A fingerprint of the one frame (step 30) of `scene` rendered at 320x240 with `options`;
  /// empty on failure.
  std::string frame(const std::string& options, const std::string& scene = "named.json") {
    const std::string out = "f" + std::to_string(++renders_);
    const Result result = run("render " + scene + " --size 320x240 --frames 30:30 --out " + out + " " + options);
    EXPECT_EQ(result.status, 0) << options << ": " << result.err;
    // A short fingerprint of the PNG, so a failed comparison prints no image bytes.
    for (const auto& entry : fs::directory_iterator(dir_ / out)) {
      if (entry.path().extension() != ".png") continue;  // the frames.csv index is there too
      return std::to_string(std::hash<std::string>{}(without_text_chunks(read_file(entry.path()))));
    }
    return "";
  }

  /// Expects exit status 2 and `message` in stderr after the program's prefix.
  void expect_usage_error(const std::string& options, const std::string& message) {
    const Result result = run("render named.json --size 320x240 --frames 30:30 --out bad " + options);
    EXPECT_EQ(result.status, 2) << options;
    EXPECT_NE(result.err.find("impulse2d: "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find(message), std::string::npos) << options << ": " << result.err;
    EXPECT_FALSE(fs::exists(dir_ / "bad")) << options;
  }

  int renders_ = 0;
};

}  // namespace

TEST_F(CliViewTest, HudAndLegendSwitches) {
  const std::string plain = frame("");
  ASSERT_FALSE(plain.empty());
  EXPECT_EQ(frame("--hud --legend"), plain);
  EXPECT_NE(frame("--no-hud"), plain);
  EXPECT_NE(frame("--no-legend"), plain);
  EXPECT_NE(frame("--no-hud"), frame("--no-legend"));
  const Result both = run("render named.json --hud --no-hud");
  EXPECT_EQ(both.status, 2) << both.err;
}

TEST_F(CliViewTest, ScalesChangeTheFrameAndAreChecked) {
  const std::string plain = frame("--no-hud --no-legend");
  EXPECT_NE(frame("--no-hud --no-legend --arrow-scale 3"), plain);
  EXPECT_NE(frame("--no-hud --no-legend --penetration-scale 200"), plain);
  EXPECT_NE(frame("--no-hud --no-legend --arrow-scale 100 --max-arrow 20"),
            frame("--no-hud --no-legend --arrow-scale 100"));
  EXPECT_NE(frame("--text-scale 2"), frame(""));
  EXPECT_EQ(frame("--text-scale 1"), frame(""));  // 1 is the automatic scale at 320x240
  expect_usage_error("--arrow-scale 0", "--arrow-scale 0: must be in 0.001..1000");
  expect_usage_error("--penetration-scale 0.5", "--penetration-scale 0.5: must be in 1..1000");
  expect_usage_error("--text-scale 0", "--text-scale 0: must be in 1..16");
  expect_usage_error("--max-arrow 2", "--max-arrow 2: must be in 8..4096");
}

TEST_F(CliViewTest, CameraOptions) {
  const std::string plain = frame("--no-hud --no-legend");
  EXPECT_NE(frame("--no-hud --no-legend --view -3,-1:3,4"), plain);
  EXPECT_NE(frame("--no-hud --no-legend --zoom 2"), plain);
  const std::string followed = frame("--no-hud --no-legend --follow right");
  EXPECT_NE(followed, plain);
  EXPECT_EQ(frame("--no-hud --no-legend --follow 2"), followed);  // by name or creation index
  EXPECT_NE(frame("--no-hud --no-legend --follow 2 --zoom 3"), followed);
  expect_usage_error("--view 1,2", "--view '1,2': expected x0,y0:x1,y1");
  expect_usage_error("--view 3,0:1,4", "expected x0,y0:x1,y1");
  expect_usage_error("--zoom 0", "--zoom 0: must be in 0.01..100");
  expect_usage_error("--follow nobody", "--follow 'nobody': no body of scene named has that name");
  expect_usage_error("--follow 9", "--follow 9: body 9 does not exist");
  expect_usage_error("--view -3,-1:3,4 --follow 1", "--view and --follow both choose the camera");
}

TEST_F(CliViewTest, CameraOptionsWorkOnBuiltInScenes) {
  const std::string plain = frame("--no-hud", "pyramid");
  EXPECT_NE(frame("--no-hud --zoom 2", "pyramid"), plain);
  EXPECT_NE(frame("--no-hud --follow 5", "pyramid"), plain);
  EXPECT_NE(frame("--no-hud --view 0,0:4,3", "pyramid"), plain);
  EXPECT_NE(frame("--no-hud --highlight 5", "pyramid"), plain);
}

TEST_F(CliViewTest, HighlightAndBodyNames) {
  const std::string plain = frame("--no-hud --no-legend");
  const std::string highlighted = frame("--no-hud --no-legend --highlight left");
  EXPECT_NE(highlighted, plain);
  EXPECT_EQ(frame("--no-hud --no-legend --highlight 1"), highlighted);
  expect_usage_error("--highlight 7", "--highlight 7: body 7 does not exist");
  // The ids overlay shows names: the same scene without names draws other labels.
  std::string unnamed = named_scene;
  for (const char* name : {"\"name\": \"ground\", ", "\"name\": \"left\", ", "\"name\": \"right\", "}) {
    unnamed.erase(unnamed.find(name), std::string(name).size());
  }
  std::ofstream(dir_ / "unnamed.json") << unnamed;
  const std::string with_names = frame("--no-hud --no-legend --overlays ids");
  std::string without_names = frame("--no-hud --no-legend --overlays ids", "unnamed.json");
  EXPECT_NE(with_names, without_names);
}

TEST_F(CliViewTest, HudSettingsAndTimingsOnRequest) {
  const std::string plain = frame("");
  EXPECT_NE(frame("--hud-settings"), plain);
  EXPECT_NE(frame("--hud-timings"), plain);  // wall-clock: only on request, never in goldens
}

TEST_F(CliViewTest, SceneFileViewBlockDoesWhatTheOptionsDo) {
  std::string text = named_scene;
  text.insert(text.rfind('}'), R"(, "view": {"hud": false, "legend": false, "arrow_scale": 3, "penetration_scale": 200,
    "max_arrow_pixels": 10, "text_scale": 2, "highlight": "left"})");
  std::ofstream(dir_ / "viewed.json") << text;
  EXPECT_EQ(frame("", "viewed.json"),
            frame("--no-hud --no-legend --arrow-scale 3 --penetration-scale 200 --max-arrow 10 --text-scale 2 "
                  "--highlight left"));
  std::string bad = named_scene;
  bad.insert(bad.rfind('}'), R"(, "view": {"hud": false, "legend_size": 3})");
  std::ofstream(dir_ / "bad_view.json") << bad;
  const Result result = run("render bad_view.json");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("view"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("legend_size"), std::string::npos) << result.err;
}

TEST_F(CliViewTest, SheetTakesTheViewOptions) {
  const Result plain = run("sheet named.json --frames 10:30:10 --tile 160x120 --out a.png");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const Result bare = run("sheet named.json --frames 10:30:10 --tile 160x120 --out b.png --no-legend --zoom 2");
  ASSERT_EQ(bare.status, 0) << bare.err;
  EXPECT_TRUE(read_file(dir_ / "a.png") != read_file(dir_ / "b.png"));
}

TEST_F(CliViewTest, IslandsFeatureIdsAndTimeline) {
  const std::string plain = frame("--no-hud --no-legend");
  EXPECT_NE(frame("--no-hud --no-legend --islands"), plain);
  EXPECT_NE(frame("--no-hud --no-legend --feature-ids"), plain);
  // The timeline adds a strip under the frame: the PNG is 64 rows taller at 320x240.
  const Result result = run("render named.json --size 320x240 --frames 10:30:10 --out t --timeline");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string png = read_file(dir_ / "t" / "named_00002.png");  // frames 0, 1, 2: steps 10, 20, 30
  ASSERT_GT(png.size(), 24u);
  const auto byte = [&](std::size_t i) { return static_cast<unsigned>(static_cast<unsigned char>(png[i])); };
  EXPECT_EQ((byte(16) << 24) | (byte(17) << 16) | (byte(18) << 8) | byte(19), 320u);  // IHDR width
  EXPECT_EQ((byte(20) << 24) | (byte(21) << 16) | (byte(22) << 8) | byte(23), 304u);  // IHDR height
  // Each frame marks its own step.
  EXPECT_TRUE(read_file(dir_ / "t" / "named_00000.png") != read_file(dir_ / "t" / "named_00001.png"));
  // The sheet has no --timeline (a strip per tile would repeat the same run) and no HUD.
  EXPECT_EQ(run("sheet named.json --timeline").status, 2);
  EXPECT_EQ(run("sheet named.json --no-hud").status, 2);
  EXPECT_EQ(run("sheet named.json --hud-settings").status, 2);
  // The same switches from the scene file.
  std::string text = named_scene;
  text.insert(text.rfind('}'), R"(, "view": {"hud": false, "legend": false, "islands": true, "feature_ids": true})");
  std::ofstream(dir_ / "islands.json") << text;
  EXPECT_EQ(frame("", "islands.json"), frame("--no-hud --no-legend --islands --feature-ids"));
}

TEST_F(CliViewTest, NativeVectorWidth128IsAClearErrorNotAnAbort) {
  const Result result = run("render named.json --size 320x240 --frames 30:30 --out w", "LP_NATIVE_VECTOR_WIDTH=128");
  EXPECT_EQ(result.status, 1) << result.err;
  EXPECT_NE(result.err.find("impulse2d: error: "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("LP_NATIVE_VECTOR_WIDTH=128 is set"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "w"));  // nothing half-written
}
