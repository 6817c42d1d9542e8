// The browser viewer (issue 15.7): `impulse2d render --html` writes <scene>.html beside the
// frames, listing every frame file in order with its step, time, energy and contacts as JSON,
// referencing only files that exist and nothing on the network, with overlay variants
// pre-rendered into <scene>.overlays/; headless Chromium, where it is installed, opens the page
// at #frame=3&overlays=normals and its screenshot matches golden_images/viewer/.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "frames/html_viewer.h"
#include "frames/overlay_variants.h"
#include "scene/overlays.h"
#include "tests/support/cli_test_support.h"
#include "tests/app/headless_chromium.h"
#include "tests/app/screenshot_golden.h"
#include "tests/support/viewer_golden.h"

using namespace cli_test;

namespace {

/// The rows of a `<scene>_frames.csv` after its header, each split at commas.
std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::istringstream text(read_file(path));
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(text, line);
  while (std::getline(text, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

/// The JSON the page embeds, {"frames": [...], "variants": [...]} (null when it has none).
nlohmann::json embedded_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"viewer-data\">";
  const std::size_t begin = html.find(open);
  if (begin == std::string::npos) return nullptr;
  const std::size_t end = html.find("</script>", begin);
  return nlohmann::json::parse(html.substr(begin + open.size(), end - begin - open.size()));
}

}  // namespace

TEST_F(CliTest, HtmlViewerListsEveryFrameWithItsData) {
  const Result result =
      run("render tutorial --frames 0:40:10 --size 160x120 --overlays contacts --html -o view");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("viewer view/tutorial.html"), std::string::npos) << result.out;
  const fs::path page = dir_ / "view" / "tutorial.html";
  ASSERT_TRUE(fs::exists(page));
  const std::string html = read_file(page);

  // Every frame file, in order, with the steps and times of the index.
  const std::vector<std::vector<std::string>> rows = csv_rows(dir_ / "view" / "tutorial_frames.csv");
  ASSERT_EQ(rows.size(), 5u);
  const nlohmann::json data = embedded_data(html);
  const nlohmann::json frames = data["frames"];
  ASSERT_TRUE(frames.is_array()) << "no embedded frame data";
  ASSERT_EQ(frames.size(), rows.size());
  std::size_t previous = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    EXPECT_EQ(frames[i]["frame"].get<std::int64_t>(), std::stoll(rows[i][0]));
    EXPECT_EQ(frames[i]["step"].get<std::int64_t>(), std::stoll(rows[i][1]));
    EXPECT_NEAR(frames[i]["time"].get<double>(), std::stod(rows[i][2]), 1e-6);
    EXPECT_EQ(frames[i]["file"].get<std::string>(), rows[i][3]);
    EXPECT_TRUE(frames[i]["energy"].is_number());
    EXPECT_GE(frames[i]["contacts"].get<std::int64_t>(), 0);
    const std::size_t at = html.find("\"" + rows[i][3] + "\"");
    ASSERT_NE(at, std::string::npos);
    EXPECT_GT(at, previous);
    previous = at;
    EXPECT_TRUE(fs::exists(dir_ / "view" / rows[i][3]));
  }
  // The tutorial's first bodies land by step 30: no contacts at step 0, some at step 30.
  EXPECT_EQ(frames[0]["contacts"].get<std::int64_t>(), 0);
  EXPECT_GT(frames[3]["contacts"].get<std::int64_t>(), 0);

  // The overlay switch: the frames beside the page (with "contacts"), then without overlays
  // and one group at a time, each a directory of the same files.
  std::vector<std::string> labels;
  for (const nlohmann::json& variant : data["variants"]) {
    labels.push_back(variant["label"].get<std::string>());
    for (const std::vector<std::string>& row : rows) {
      const fs::path file = dir_ / "view" / variant["directory"].get<std::string>() / row[3];
      EXPECT_TRUE(fs::is_regular_file(file)) << file;
    }
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"contacts", "none", "points", "normals", "impulses",
                                              "penetration"}));
  EXPECT_EQ(data["variants"][1]["directory"], "tutorial.overlays/none");

  // Every src/href names a file beside the page; nothing comes from the network.
  const std::regex reference("(src|href)\\s*=\\s*\"([^\"]*)\"");
  for (auto match = std::sregex_iterator(html.begin(), html.end(), reference);
       match != std::sregex_iterator(); ++match) {
    EXPECT_TRUE(fs::exists(dir_ / "view" / (*match)[2].str())) << (*match)[0];
  }
  EXPECT_EQ(html.find("http:"), std::string::npos);
  EXPECT_EQ(html.find("https:"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);

  // Frames, index, page and variants, nothing else (no temporary file left behind).
  EXPECT_EQ(files().size(), rows.size() + 2 + (labels.size() - 1) * rows.size());
  EXPECT_FALSE(fs::exists(dir_ / "view" / "tutorial.overlays" / "contacts"));
}

// With the events overlay each frame carries the events of the steps since the frame before
// (issue 32): the sensors scene's three balls enter the sensor box by step 57 and the bouncy
// ball lands at step 57, so frames every 4 steps up to 60 count 3 sensor begins and a hit in
// all, none lost between frames. Without the overlay the frames carry no events.
TEST_F(CliTest, HtmlViewerWithTheEventsOverlayCountsEachFramesEvents) {
  ASSERT_EQ(run("render sensors --frames 0:60:4 --size 160x120 --overlays events --html -o view --quiet").status, 0);
  const nlohmann::json frames = embedded_data(read_file(dir_ / "view" / "sensors.html"))["frames"];
  ASSERT_EQ(frames.size(), 16u);
  int sensor_begins = 0, hits = 0;
  for (const nlohmann::json& frame : frames) {
    ASSERT_TRUE(frame.contains("events")) << frame.dump();
    sensor_begins += frame["events"]["sensor_begin"].get<int>();
    hits += frame["events"]["hit"].get<int>();
  }
  EXPECT_EQ(sensor_begins, 3);
  EXPECT_EQ(hits, 1);
  ASSERT_EQ(run("render sensors --frames 0:60:4 --size 160x120 --overlays none --html -o plain --quiet").status, 0);
  const nlohmann::json plain = embedded_data(read_file(dir_ / "plain" / "sensors.html"))["frames"];
  ASSERT_EQ(plain.size(), 16u);
  EXPECT_FALSE(plain[15].contains("events"));
}

TEST_F(CliTest, HtmlWithoutFramesIsBadUsage) {
  const Result result = run("render tutorial --html --no-frames --video v.webm");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(result.err.rfind("impulse2d: --html", 0), 0u) << result.err;
  EXPECT_TRUE(files().empty());
}

TEST_F(CliTest, HtmlViewerOfAnEarlierRunIsReplacedOnlyWithClean) {
  const std::string render = "render tutorial --frames 0:20:10 --size 160x120 -o view --quiet";
  ASSERT_EQ(run(render + " --html --overlays normals").status, 0);
  ASSERT_TRUE(fs::exists(dir_ / "view" / "tutorial.overlays" / "none" / "tutorial_00002.png"));
  const Result again = run(render + " --html");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("--clean"), std::string::npos) << again.err;
  // A new run without --html removes the old page and variants, which would show old data.
  ASSERT_EQ(run(render + " --clean").status, 0);
  EXPECT_FALSE(fs::exists(dir_ / "view" / "tutorial.html"));
  EXPECT_FALSE(fs::exists(dir_ / "view" / "tutorial.overlays"));
  EXPECT_EQ(files().size(), 4u);
}

TEST(HtmlViewer, OverlayVariantsAreNoneAndEachGroupAlone) {
  using impulse2d::demos::overlay_variants;
  using impulse2d::demos::parse_overlays;
  const auto names = [](const std::string& overlays) {
    std::vector<std::string> found;
    for (const auto& variant : overlay_variants(parse_overlays(overlays))) found.push_back(variant.name);
    return found;
  };
  EXPECT_TRUE(names("none").empty());
  EXPECT_EQ(names("normals"), (std::vector<std::string>{"none"}));
  EXPECT_EQ(names("penetration,normals"), (std::vector<std::string>{"none", "normals", "penetration"}));
  EXPECT_EQ(names("contacts"),
            (std::vector<std::string>{"none", "points", "normals", "impulses", "penetration"}));
  // Shapes stay in every variant; each group's flags are its own.
  const auto variants = overlay_variants(parse_overlays("normals,aabbs"));
  ASSERT_EQ(variants.size(), 3u);
  EXPECT_EQ(variants[0].flags, parse_overlays("none"));
  EXPECT_EQ(variants[1].flags, parse_overlays("normals"));
  EXPECT_EQ(variants[2].flags, parse_overlays("aabbs"));
}

TEST(HtmlViewer, TextAndDataCannotBreakOutOfThePage) {
  impulse2d::demos::ViewerPage page;
  page.title = "a <b>title</b> & @FRAMES@";
  page.frames.push_back({{0, 0, 0.0, "x</script><script>alert(1)</script>.png"}, 1.0, 0, {}});
  const std::string html = impulse2d::demos::html_viewer_page(page);
  EXPECT_NE(html.find("a &lt;b&gt;title&lt;/b&gt; &amp; @FRAMES@"), std::string::npos);
  EXPECT_EQ(html.find("alert(1)</script>"), std::string::npos);
  EXPECT_EQ(embedded_data(html)["frames"][0]["file"], "x</script><script>alert(1)</script>.png");
}

TEST_F(CliTest, HtmlViewerInHeadlessChromiumMatchesItsGolden) {
  if (!impulse2d::testing::have_chromium()) {
    GTEST_SKIP() << "chromium is not on PATH (Debian package 'chromium', installed by "
                    "scripts/setup.sh): the page is not checked in a real browser";
  }
  ASSERT_TRUE(fs::exists(impulse2d::testing::dejavu_font_dir() / "DejaVuSans.ttf"))
      << "the golden's text is drawn in DejaVu Sans: install fonts-dejavu-core (scripts/setup.sh)";
  ASSERT_EQ(run("render tutorial --frames 0:40:10 --size 240x180 --overlays contacts --html "
                "-o view --quiet").status, 0);
  // Frame 3 (step 30, the first bodies resting) with the normals variant instead of the
  // frames' own "contacts", chosen through the address as a bookmark would.
  impulse2d::testing::ChromiumRun browser;
  browser.url = "file://" + (dir_ / "view" / "tutorial.html").string() + "#frame=3&overlays=normals";
  browser.work_dir = dir_ / "browser";
  fs::create_directories(browser.work_dir);
  const impulse2d::testing::ChromiumResult shown = impulse2d::testing::load_in_chromium(browser);
  ASSERT_EQ(shown.status, 0) << shown.describe();

  // What the page's script did: the frame, its step and the variant's file.
  const std::string& dom = shown.dom;
  EXPECT_NE(dom.find("<body data-frame=\"3\" data-overlays=\"normals\">"), std::string::npos) << dom;
  EXPECT_NE(dom.find("<b id=\"frame-number\">3 / 4</b>"), std::string::npos) << dom;
  EXPECT_NE(dom.find("<b id=\"step\">30</b>"), std::string::npos) << dom;
  EXPECT_NE(dom.find("src=\"tutorial.overlays/normals/tutorial_00003.png\""), std::string::npos)
      << dom;

  // What it looked like.
  ASSERT_TRUE(fs::exists(shown.screenshot)) << shown.describe();
  const impulse2d::testing::ScreenshotCheck check = impulse2d::testing::check_screenshot(
      impulse2d::testing::kViewerGolden, shown.screenshot,
      impulse2d::golden::check_settings_from_environment(IMPULSE2D_GOLDEN_DIR,
                                                         IMPULSE2D_GOLDEN_ARTIFACT_DIR));
  EXPECT_TRUE(check.passed) << check.message;
}
