/// @file test_golden_command.cpp
/// `impulse2d golden` on a copy of examples/golden_project, as a user's CI runs it: the
/// committed goldens pass; a physics change fails as *behaviour changed*, a rounding-sized
/// change of one body's position as *numerical noise*, a pixel change with the physics
/// untouched as *rasterisation differs*, a missing golden as *missing golden* (exit 1 each,
/// JUnit failure type named); update writes it; bad input exits 2 with nothing written;
/// CI refuses update.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/golden/test_golden_temp_dir.h"
#include "image/file_io.h"
#include "image/image.h"
#include "image/png.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Result {
  int status = -1;
  std::string out;
  std::string err;
};

class GoldenCommand : public ::testing::Test {
 protected:
  GoldenCommand() {
    fs::copy(IMPULSE2D_EXAMPLE_PROJECT, project_, fs::copy_options::recursive);
  }

  /// Runs `impulse2d golden <arguments>` in the project copy (`environment` prefixed).
  Result run(const std::string& arguments, const std::string& environment = "CI=") const {
    const fs::path out = temp_.path() / "stdout.txt";
    const fs::path err = temp_.path() / "stderr.txt";
    const std::string command = "cd '" + project_.string() + "' && " + environment + " '" +
                                IMPULSE2D_CLI + "' golden " + arguments + " > '" + out.string() +
                                "' 2> '" + err.string() + "'";
    const int status = std::system(command.c_str());
    Result result;
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = image::read_text_file(out);
    result.err = image::read_text_file(err);
    return result;
  }

  Result check(const std::string& extra = "") const {
    return run("check scenes/dominoes.json scenes/cannonball.json --junit junit.xml " + extra);
  }

  /// Edits the scene file `name` (in scenes/) as JSON.
  void edit_scene(const std::string& name, const std::function<void(json&)>& change) const {
    const fs::path file = project_ / "scenes" / name;
    json scene = json::parse(image::read_text_file(file));
    change(scene);
    image::write_text_file_atomically(file, scene.dump(2));
  }

  std::string junit() const { return image::read_text_file(project_ / "junit.xml"); }

  testing::TempDir temp_;
  fs::path project_ = temp_.path() / "project";
};

TEST_F(GoldenCommand, CommittedGoldensPassWithJUnitAndReport) {
  const Result result = check("--repeat 2");
  EXPECT_EQ(result.status, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("6 of 6 goldens match"), std::string::npos) << result.out;
  EXPECT_NE(junit().find("tests=\"6\" failures=\"0\""), std::string::npos) << junit();
  EXPECT_TRUE(fs::exists(project_ / "golden_artifacts" / "index.html"));
}

TEST_F(GoldenCommand, PhysicsChangeIsBehaviourChanged) {
  edit_scene("cannonball.json", [](json& scene) {
    scene["bodies"][1]["linear_damping"] = 0.315;  // 5% more damping
  });
  const Result result = check();
  EXPECT_EQ(result.status, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("golden 'cannonball/flight': behaviour changed"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("3 of 6 goldens match"), std::string::npos) << result.out;
  EXPECT_NE(junit().find("type=\"behaviour_changed\""), std::string::npos) << junit();
}

TEST_F(GoldenCommand, RoundingSizedChangeIsNumericalNoise) {
  edit_scene("dominoes.json", [](json& scene) {
    // Domino d3's x moved by one float ulp (-1.8 -> the next float towards zero).
    scene["bodies"][4]["position"][0] = std::nextafter(-1.8f, 0.0f);
  });
  const Result result = run("check scenes/dominoes.json --junit junit.xml");
  EXPECT_EQ(result.status, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("golden 'dominoes/falling': numerical noise"), std::string::npos)
      << result.out;
  // By 'down' rounding alone moves the dominoes up to 13 cm, more than 1 % of the scene's
  // size (5.4 cm): noise could explain the change there, and so could a real one.
  EXPECT_NE(result.out.find("golden 'dominoes/down': cannot tell"), std::string::npos)
      << result.out;
  EXPECT_EQ(result.out.find("behaviour changed"), std::string::npos) << result.out;
}

/// The PNG this run's renderer compares `dominoes/<name>` with: the golden itself, or, when
/// another renderer drew the goldens (e.g. GALLIUM_DRIVER=softpipe), that renderer's baseline,
/// written first by `golden update` when it has none.
fs::path pixel_baseline(const fs::path& goldens, const std::string& name,
                        const std::function<Result(const std::string&)>& run) {
  const Result probe = run("check scenes/dominoes.json");
  if (probe.out.find("no baseline for this renderer") == std::string::npos) {
    return goldens / (name + ".png");
  }
  const Result update = run("update scenes/dominoes.json");
  EXPECT_EQ(update.status, 0) << update.out << update.err;
  for (const auto& entry : fs::directory_iterator(goldens)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind(name + "@", 0) == 0 && entry.path().extension() == ".png") return entry.path();
  }
  ADD_FAILURE() << "golden update wrote no baseline for this renderer: " << update.out;
  return goldens / (name + ".png");
}

TEST_F(GoldenCommand, PixelChangeWithTheSamePhysicsIsRasterisation) {
  // On the goldens' renderer the golden's pixels change; on another one, its baseline's.
  const fs::path golden = pixel_baseline(project_ / "scenes" / "goldens" / "dominoes", "start",
                                         [this](const std::string& arguments) {
                                           return run(arguments);
                                         });
  image::Image image = image::load_png(golden);
  image::Rgba pixel = image.pixel(300, 150);
  pixel.r = static_cast<std::uint8_t>(pixel.r ^ 0x40);
  image.set_pixel(300, 150, pixel);
  image::save_png(golden, image);
  const Result result = check();
  EXPECT_EQ(result.status, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("golden 'dominoes/start': rasterisation differs"), std::string::npos)
      << result.out;
  EXPECT_NE(junit().find("type=\"rasterisation_differs\""), std::string::npos) << junit();
}

TEST_F(GoldenCommand, RequirePixelsFailsWithoutABaselineForTheRenderer) {
  // softpipe has no baseline in the example project: only the physics could be checked.
  const std::string softpipe = "CI= GALLIUM_DRIVER=softpipe";
  const Result required =
      run("check scenes/dominoes.json --require-pixels --junit junit.xml", softpipe);
  EXPECT_EQ(required.status, 1) << required.out << required.err;
  EXPECT_NE(required.out.find("FAIL golden 'dominoes/start': renderer baseline required: "
                              "pixels are required"),
            std::string::npos)
      << required.out;
  EXPECT_NE(required.out.find("pixels required but not checked: 3 of 3 frames drawn by "
                              "'softpipe"),
            std::string::npos)
      << required.out;
  EXPECT_NE(junit().find("failures=\"3\""), std::string::npos) << junit();
  EXPECT_NE(junit().find("type=\"renderer_baseline_required\""), std::string::npos) << junit();

  // The environment variable does the same for ctest and scripts; a bad value is bad input.
  const Result by_environment =
      run("check scenes/dominoes.json", softpipe + " IMPULSE2D_REQUIRE_PIXELS=1");
  EXPECT_EQ(by_environment.status, 1) << by_environment.out << by_environment.err;
  const Result bad = run("check scenes/dominoes.json", softpipe + " IMPULSE2D_REQUIRE_PIXELS=yes");
  EXPECT_EQ(bad.status, 2) << bad.out << bad.err;
  EXPECT_NE(bad.err.find("IMPULSE2D_REQUIRE_PIXELS='yes'"), std::string::npos) << bad.err;

  // With the renderer's baselines written, pixels are checked and the requirement is met.
  EXPECT_EQ(run("update scenes/dominoes.json", softpipe).status, 0);
  const Result met = run("check scenes/dominoes.json --require-pixels", softpipe);
  EXPECT_EQ(met.status, 0) << met.out << met.err;
  EXPECT_EQ(met.out.find("pixels"), std::string::npos) << met.out;
}

TEST_F(GoldenCommand, MissingGoldenFailsAndUpdateWritesIt) {
  const fs::path golden = project_ / "scenes" / "goldens" / "cannonball" / "rest";
  fs::remove(golden.string() + ".png");
  fs::remove(golden.string() + ".json");
  const Result missing = check();
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.out.find("golden 'cannonball/rest': missing golden"), std::string::npos)
      << missing.out;
  const Result refused = run("update scenes/cannonball.json", "CI=yes");
  EXPECT_EQ(refused.status, 2) << refused.out << refused.err;
  EXPECT_NE(refused.err.find("CI never writes its own goldens"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(golden.string() + ".png"));
  const Result update = run("update scenes/cannonball.json");
  EXPECT_EQ(update.status, 0) << update.out << update.err;
  EXPECT_NE(update.out.find("WROTE cannonball/rest"), std::string::npos) << update.out;
  EXPECT_EQ(check().status, 0);
}

TEST_F(GoldenCommand, AnotherRendererChecksThePhysicsUntilItHasItsOwnBaseline) {
  const std::string softpipe = "CI= GALLIUM_DRIVER=softpipe";
  const fs::path goldens = project_ / "scenes" / "goldens" / "dominoes";
  const std::string primary = image::read_text_file(goldens / "start.png");
  const Result physics_only = run("check scenes/dominoes.json --junit junit.xml", softpipe);
  EXPECT_EQ(physics_only.status, 0) << physics_only.out << physics_only.err;
  EXPECT_NE(physics_only.out.find("skip golden 'dominoes/start': no baseline for this renderer: "
                                  "physics checked and matches"),
            std::string::npos)
      << physics_only.out;
  EXPECT_NE(physics_only.out.find("impulse2d golden update"), std::string::npos);
  EXPECT_NE(physics_only.out.find("(3 by their physics only"), std::string::npos);
  // Said once per run: which renderer lacks baselines and how many frames went unchecked.
  EXPECT_NE(physics_only.out.find("pixels unchecked: 3 of 3 frames drawn by 'softpipe"),
            std::string::npos)
      << physics_only.out;
  EXPECT_NE(junit().find("skipped=\"3\""), std::string::npos) << junit();

  // The physics is still checked on that renderer.
  const fs::path scene = project_ / "scenes" / "dominoes.json";
  const std::string original_scene = image::read_text_file(scene);
  edit_scene("dominoes.json", [](json& file) { file["events"][0]["impulse"][0] = 0.42; });
  const Result changed = run("check scenes/dominoes.json", softpipe);
  EXPECT_EQ(changed.status, 1) << changed.out;
  EXPECT_NE(changed.out.find("golden 'dominoes/falling': behaviour changed"), std::string::npos)
      << changed.out;
  EXPECT_NE(changed.out.find("Image: not compared (no baseline for this renderer"),
            std::string::npos)
      << changed.out;
  image::write_text_file_atomically(scene, original_scene);

  // update adds the renderer's baseline beside the golden, which stays as it was.
  const Result update = run("update scenes/dominoes.json", softpipe);
  EXPECT_EQ(update.status, 0) << update.out << update.err;
  EXPECT_NE(update.out.find("WROTE dominoes/start"), std::string::npos) << update.out;
  EXPECT_EQ(image::read_text_file(goldens / "start.png"), primary);
  int baselines = 0;
  for (const auto& entry : fs::directory_iterator(goldens)) {
    baselines += entry.path().filename().string().rfind("start@softpipe-", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(baselines, 2) << "start@softpipe-<key>.png and its .json";
  const Result pixels = run("check scenes/dominoes.json", softpipe);
  EXPECT_EQ(pixels.status, 0) << pixels.out;
  EXPECT_NE(pixels.out.find("ok   dominoes/start"), std::string::npos) << pixels.out;
  EXPECT_EQ(check().status, 0) << "the default renderer still uses the golden itself";
}

TEST_F(GoldenCommand, BadBlockIsAnInputErrorWithNothingWritten) {
  edit_scene("dominoes.json", [](json& scene) { scene["golden"]["frames"][1]["step"] = -3; });
  const Result result = check();
  EXPECT_EQ(result.status, 2) << result.out << result.err;
  EXPECT_NE(result.err.find("scenes/dominoes.json: field 'golden.frames[1].step'"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(project_ / "golden_artifacts"));
  EXPECT_FALSE(fs::exists(project_ / "junit.xml"));
}

TEST_F(GoldenCommand, ReportDirectoryOfSomethingElseIsNotEmptied) {
  fs::create_directories(project_ / "mine");
  image::write_text_file_atomically(project_ / "mine" / "notes.txt", "keep");
  const Result result = check("--report mine");
  EXPECT_EQ(result.status, 2) << result.out << result.err;
  EXPECT_TRUE(fs::exists(project_ / "mine" / "notes.txt"));
}

}  // namespace
}  // namespace impulse2d::golden
