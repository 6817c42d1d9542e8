// The impulse2d program run as a subprocess: commands, exit codes (0 / 1 runtime / 2 usage),
// messages for bad input, and no partial files left behind. `trace` of a JSON projectile
// matches the exact answer up to semi-implicit Euler's known error g t dt / 2.
#include "core/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

using namespace cli_test;

namespace {

const char* const projectile = R"({
  "settings": {"gravity": [0, -9.81], "time_step": 0.01},
  "model": {"shapes": ["circle"], "rotation": false, "friction": false, "restitution": false},
  "bodies": [{"name": "ball", "shape": {"type": "circle", "radius": 0.25},
              "position": [0, 100], "velocity": [3, 12], "material": "Rock"}]
})";

}  // namespace

TEST_F(CliTest, ListShowsEveryBuiltInSceneWithItsModel) {
  const Result result = run("list");
  EXPECT_EQ(result.status, 0) << result.err;
  for (const char* name : {"tutorial", "materials", "friction_ramp", "shape_pairs", "pyramid",
                           "stack", "newtons_cradle", "bullet", "ball_pit", "random_polygons"}) {
    EXPECT_NE(result.out.find(std::string(name) + "\n"), std::string::npos) << name;
  }
  EXPECT_NE(result.out.find("model: shapes box, rotation off"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("--param rows=20"), std::string::npos);
}

TEST_F(CliTest, HelpWorksOnEveryCommand) {
  for (const char* command : {"", "list ", "render ", "trace ", "sheet ", "diff "}) {
    const Result result = run(std::string(command) + "--help");
    EXPECT_EQ(result.status, 0) << command << result.err;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}

TEST_F(CliTest, RendersAFrameSequenceAndPrintsWhereItWent) {
  const Result result =
      run("render pyramid --param rows=4 --frames 0:20:10 --size 160x120 --overlays "
          "normals,penetration --out frames");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("wrote 3 frames of pyramid to frames/"), std::string::npos)
      << result.out;
  for (const char* name :
       {"frames/pyramid_00000.png", "frames/pyramid_00001.png", "frames/pyramid_00002.png"}) {
    const std::string png = read_file(dir_ / name);
    ASSERT_GT(png.size(), 8u) << name;
    EXPECT_EQ(png.substr(1, 3), "PNG");
  }
  EXPECT_EQ(files().size(), 4u);  // and frames/pyramid_frames.csv
  // Not a terminal: plain progress lines on stderr.
  EXPECT_NE(result.err.find("pyramid: 3/3 frames"), std::string::npos) << result.err;
}

TEST_F(CliTest, BackendOptionAndVariableGiveTheSameFiles) {
  const std::string frames = "render pyramid --param rows=4 --frames 0:20:20 --size 160x120 ";
  ASSERT_EQ(run(frames + "--backend osmesa --out osmesa").status, 0);
  ASSERT_EQ(run(frames + "--backend egl --out egl").status, 0);
  ASSERT_EQ(run(frames + "--out variable", "IMPULSE2D_BACKEND=egl").status, 0);
  for (const char* name : {"pyramid_00000.png", "pyramid_00001.png"}) {
    const std::string reference = read_file(dir_ / "osmesa" / name);
    ASSERT_GT(reference.size(), 8u) << name;
    EXPECT_TRUE(read_file(dir_ / "egl" / name) == reference) << name << " differs with --backend egl";
    EXPECT_TRUE(read_file(dir_ / "variable" / name) == reference) << name << " differs with IMPULSE2D_BACKEND=egl";
  }
}

TEST_F(CliTest, BadBackendIsBadUsageBeforeAnyFile) {
  const Result option = run("render pyramid --backend vulkan --out frames");
  EXPECT_EQ(option.status, 2);
  EXPECT_NE(option.err.find("--backend"), std::string::npos) << option.err;
  const Result variable = run("render pyramid --out frames", "IMPULSE2D_BACKEND=vulkan");
  EXPECT_EQ(variable.status, 2);
  EXPECT_NE(variable.err.find("environment variable IMPULSE2D_BACKEND: unknown renderer backend "
                              "'vulkan' (use osmesa or egl)"),
            std::string::npos)
      << variable.err;
  EXPECT_TRUE(files().empty());
}

TEST_F(CliTest, WithoutArgumentsRendersTheDefaultDemoIntoOut) {
  const Result result = run("");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("of tutorial to out/"), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(dir_ / "out/tutorial_00000.png"));
  EXPECT_TRUE(fs::exists(dir_ / "out/tutorial_00300.png"));  // 301 frames: steps 0, 3, .., 900
  // With the contact overlays the README promises: step 300 as `render --overlays` draws it
  // (as frame 100 too: the HUD names the frame where it differs from the step).
  ASSERT_EQ(
      run("render tutorial --frames 0:300:3 --overlays normals,impulses,penetration -o ref").status,
      0);
  EXPECT_EQ(run("diff out/tutorial_00100.png ref/tutorial_00100.png").status, 0);
  ASSERT_EQ(run("render tutorial --frames 0:300:3 -o plain").status, 0);
  EXPECT_EQ(run("diff out/tutorial_00100.png plain/tutorial_00100.png").status, 1);
}

TEST_F(CliTest, ContactSheetIsOnePng) {
  const Result result =
      run("sheet pyramid --param rows=3 --count 3 --tile 160x120 --out sheet/p.png");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(read_file(dir_ / "sheet/p.png").substr(1, 3), "PNG");
  EXPECT_NE(result.out.find("contact sheet of 3 frames"), std::string::npos) << result.out;
}

TEST_F(CliTest, DiffSaysSameForTwoRendersAndWritesAReportForDifferentFrames) {
  ASSERT_EQ(run("render pyramid --param rows=3 --frames 0,30 --size 160x120 --out f").status, 0);
  ASSERT_EQ(run("render pyramid --param rows=3 --frames 0 --size 160x120 --out g").status, 0);
  const Result same = run("diff f/pyramid_00000.png g/pyramid_00000.png --out report");
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  EXPECT_FALSE(fs::exists(dir_ / "report/index.html"));  // nothing to show for an exact match
  const Result different = run("diff f/pyramid_00000.png f/pyramid_00001.png --out report");
  EXPECT_EQ(different.status, 1) << different.out << different.err;
  EXPECT_NE(different.out.find("differ"), std::string::npos) << different.out;
  for (const char* name : {"report/index.html", "report/diff.png", "report/heatmap.png",
                           "report/metrics.json", "report/expected.png", "report/actual.png"}) {
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  }
  const Result missing = run("diff f/pyramid_00000.png nowhere.png");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("nowhere.png"), std::string::npos) << missing.err;
}

TEST_F(CliTest, TrailsAddTheBodiesPathsToTheFrames) {
  ASSERT_EQ(run("render tutorial --frames 120 --size 320x240 --out plain").status, 0);
  const Result trails = run("render tutorial --frames 120 --size 320x240 --trails dynamic --out t");
  ASSERT_EQ(trails.status, 0) << trails.err;
  EXPECT_EQ(run("diff plain/tutorial_00000.png t/tutorial_00000.png").status, 1);
  const Result bad = run("render tutorial --frames 120 --trails 3,x --out u");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--trails '3,x': 'x' is not a body index"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "u"));
}

TEST_F(CliTest, VideoIsEncodedWhenFfmpegIsInstalled) {
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "ffmpeg is not installed (optional: apt-get install ffmpeg)";
  }
  const Result result = run(
      "render pyramid --param rows=3 --frames 0:40:4 --size 160x120 --out v --video v/p.mp4");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string video = read_file(dir_ / "v/p.mp4");
  ASSERT_GT(video.size(), 12u);
  EXPECT_EQ(video.substr(4, 4), "ftyp");  // an MP4 container
  EXPECT_NE(result.out.find("v/p.mp4"), std::string::npos) << result.out;
}

namespace {

/// `text` as one word for /bin/sh (single quotes, each ' written as '\'').
std::string shell_word(const std::string& text) {
  std::string word = "'";
  for (const char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

}  // namespace

// ffmpeg is started without a shell: a --video path with quotes, spaces, `$`, `;`, a newline
// and a leading '-' runs nothing, and its missing folder is created even with --no-frames.
TEST_F(CliTest, VideoPathIsNeverReadByAShell) {
  if (!cli_test::have_ffmpeg()) {
    GTEST_SKIP() << "ffmpeg is not installed (optional: apt-get install ffmpeg)";
  }
  const std::string video = "-v x'; touch PWNED; '$HOME \"q\"\nline/t'; touch PWNED2;'.mp4";
  const Result result = run("render pyramid --param rows=3 --frames 0:20:4 --size 160x120 "
                            "--no-frames --video=" + shell_word(video));
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(read_file(dir_ / video).substr(4, 4), "ftyp");
  for (const std::string& file : files()) {
    const std::string name = fs::path(file).filename().string();
    EXPECT_TRUE(name != "PWNED" && name != "PWNED2") << file;
  }

  // The case the README's users hit: the video inside the -o folder, no frames.
  const Result inside = run(
      "render pyramid --param rows=3 --frames 0:20:4 --size 160x120 -o out/video "
      "--video out/video/p.mp4 --no-frames");
  ASSERT_EQ(inside.status, 0) << inside.err;
  EXPECT_TRUE(fs::exists(dir_ / "out/video/p.mp4"));
}

// A failing ffmpeg says how it failed (its exit status), and leaves nothing behind.
TEST_F(CliTest, FailingFfmpegIsReportedWithItsStatus) {
  fs::create_directories(dir_ / "bin");
  write_file(dir_ / "bin/ffmpeg", "#!/bin/sh\ncat > /dev/null\necho 'fake ffmpeg: no' >&2\nexit 3\n");
  fs::permissions(dir_ / "bin/ffmpeg", fs::perms::owner_all);
  const Result result =
      run("render pyramid --param rows=3 --frames 0:8:4 --size 160x120 --no-frames "
          "--video new/p.mp4",
          "PATH=\"$PWD/bin:$PATH\"");
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.err.find("video: ffmpeg failed writing new/p.mp4: exit status 3"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "new")) << "the folder made for the video is removed again";
}

TEST_F(CliTest, TraceOfAJsonProjectileMatchesTheExactAnswer) {
  write_file(dir_ / "projectile.json", projectile);
  const int steps = 200;
  const Result result =
      run("trace projectile.json --steps " + std::to_string(steps) + " --every 10");
  ASSERT_EQ(result.status, 0) << result.err;
  std::istringstream lines(result.out);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "step,t,body,x,y,angle,vx,vy,omega,contacts,energy");
  const double g = 9.81, dt = 0.01f, y0 = 100.0, v0x = 3.0, v0y = 12.0;
  // The file leaves the sub-steps at the default's: semi-implicit Euler at h = dt / substeps.
  const int substeps = impulse2d::WorldSettings{}.substeps;
  const double h = dt / substeps;
  int rows = 0;
  while (std::getline(lines, line)) {
    std::vector<double> v;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) v.push_back(std::stod(field));
    ASSERT_EQ(v.size(), 11u) << line;
    const int n = static_cast<int>(v[0]);
    const double t = n * dt;
    // Semi-implicit Euler: y_n = exact - g t h / 2; rounding: at most 2^-23 |y| per sub-step.
    const double exact = y0 + v0y * t - g * t * t / 2;
    const double integrations = n * substeps + 1.0;
    const double bound = integrations * 130.0 * std::ldexp(1.0, -23);
    EXPECT_NEAR(v[4] - exact, -g * t * h / 2, bound) << "step " << n;
    EXPECT_NEAR(v[3], v0x * t, integrations * 10.0 * std::ldexp(1.0, -23)) << "step " << n;
    EXPECT_NEAR(v[7], v0y - g * t, integrations * 20.0 * std::ldexp(1.0, -23)) << "step " << n;
    EXPECT_NEAR(v[1], t, 1e-6);
    ++rows;
  }
  EXPECT_EQ(rows, steps / 10 + 1);
}

TEST_F(CliTest, TraceAsJsonIsAValidDocument) {
  write_file(dir_ / "projectile.json", projectile);
  const Result result = run("trace projectile.json --steps 3 --format json");
  ASSERT_EQ(result.status, 0) << result.err;
  const nlohmann::json trace = nlohmann::json::parse(result.out);
  ASSERT_EQ(trace["samples"].size(), 4u);
  EXPECT_EQ(trace["samples"][3]["step"], 3);
  EXPECT_EQ(trace["samples"][3]["bodies"][0]["vx"], 3.0);
}

TEST_F(CliTest, WorkersGiveTheSameTraceAndFrames) {
  // --workers N (WorldSettings::worker_count): the states, so the trace and the frames, are
  // the same bits for any count.
  const Result single = run("trace pyramid --param rows=12 --steps 120 --every 40");
  ASSERT_EQ(single.status, 0) << single.err;
  for (const char* workers : {"2", "4"}) {
    const Result threaded =
        run(std::string("trace pyramid --param rows=12 --steps 120 --every 40 --workers ") + workers);
    ASSERT_EQ(threaded.status, 0) << threaded.err;
    EXPECT_EQ(threaded.out, single.out) << workers << " workers";
  }
  ASSERT_EQ(run("render pyramid --param rows=12 --frames 90 --size 160x120 --out one").status, 0);
  ASSERT_EQ(run("render pyramid --param rows=12 --frames 90 --size 160x120 --out two --workers 2").status, 0);
  EXPECT_EQ(read_file(dir_ / "two/pyramid_00000.png"), read_file(dir_ / "one/pyramid_00000.png"));
}

struct BadInput {
  const char* name;
  const char* scene_text;  // written to bad.json when not empty
  const char* arguments;
  int status;
  const char* message;
};

class CliBadInput : public CliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliBadInput, GivesOneClearMessageANonZeroStatusAndNoFiles) {
  const BadInput& input = GetParam();
  if (*input.scene_text != '\0') write_file(dir_ / "bad.json", input.scene_text);
  write_file(dir_ / "blocker", "a file where a directory is asked for");
  // No ffmpeg on this PATH, whether or not the machine has one.
  const Result result = run(input.arguments, "PATH=/nonexistent");
  EXPECT_EQ(result.status, input.status) << result.err;
  EXPECT_NE(result.err.find(input.message), std::string::npos) << "stderr: " << result.err;
  std::vector<std::string> left = files();
  left.erase(std::remove(left.begin(), left.end(), "bad.json"), left.end());
  left.erase(std::remove(left.begin(), left.end(), "blocker"), left.end());
  EXPECT_TRUE(left.empty()) << "left behind: " << left.front();
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "output directory left behind";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        BadInput{"UnknownScene", "", "render no_such_scene", 2, "unknown scene 'no_such_scene'"},
        BadInput{"MissingFile", "", "render missing.json", 2,
                 "missing.json: cannot open the scene file"},
        BadInput{"MalformedJson", R"({"bodies": [})", "render bad.json", 2,
                 "bad.json: bodies[0]: malformed JSON at line 1"},
        BadInput{
            "WrongType",
            R"({"bodies": [{"shape": {"type": "circle", "radius": [1]}, "position": [0, 0]}]})",
            "render bad.json", 2,
            "bad.json: bodies[0].shape.radius: expected a number, got an array"},
        BadInput{"MissingField", R"({"bodies": [{"position": [0, 0]}]})", "render bad.json", 2,
                 "bad.json: bodies[0]: give a body either \"shape\" (one shape) or \"shapes\""},
        BadInput{
            "NegativeRadius",
            R"({"bodies": [{"shape": {"type": "circle", "radius": -0.5}, "position": [0, 0]}]})",
            "render bad.json", 2, "bad.json: bodies[0].shape.radius: must be in 0.001..1000 (m; below 1 mm"},
        BadInput{
            "NegativeDensity",
            R"({"materials": {"Foam": {"density": -1, "restitution": 0, "static_friction": 0, "dynamic_friction": 0}},
                     "bodies": []})",
            "render bad.json", 2, "bad.json: materials.Foam.density: must be >= 0, got -1"},
        BadInput{
            "NotFinite",
            R"({"bodies": [{"shape": {"type": "circle", "radius": 1}, "position": [0, -Infinity]}]})",
            "trace bad.json --steps 1", 2, "bad.json: bodies[0].position[1]: malformed JSON"},
        BadInput{
            "Concave",
            R"({"bodies": [{"shape": {"type": "polygon", "vertices": [[0,0],[2,0],[1,0.2],[1,2]]}, "position": [0, 0]}]})",
            "render bad.json", 2, "bad.json: bodies[0].shape.vertices: the outline is not convex"},
        BadInput{
            "Degenerate",
            R"({"bodies": [{"shape": {"type": "polygon", "vertices": [[0,0],[1,1],[2,2]]}, "position": [0, 0]}]})",
            "render bad.json", 2, "bad.json: bodies[0].shape.vertices: "},
        BadInput{
            "UnknownMaterial",
            R"({"bodies": [{"shape": {"type": "circle", "radius": 1}, "position": [0, 0], "material": "Jelly"}]})",
            "render bad.json", 2, "bad.json: bodies[0].material: unknown material \"Jelly\""},
        BadInput{"UnknownParameter", "", "render pyramid --param cols=3", 2,
                 "unknown parameter 'cols'"},
        BadInput{"ParameterOutOfRange", "", "render pyramid --param rows=1000", 2,
                 "parameter rows: 1000 is outside 1..60"},
        BadInput{"FramesAfterTheRun", "", "render bullet --frames 0:500", 2,
                 "ends at step 500, after the end of the run"},
        BadInput{"FramesSelectNothing", "", "render bullet --frames 200:", 2,
                 "selects no step of the run"},
        BadInput{"BadSize", "", "render bullet --size 10x10", 2, "--size '10x10'"},
        BadInput{"BadOverlay", "", "render bullet --overlays sparkles", 2,
                 "unknown overlay 'sparkles'"},
        BadInput{"BadTheme", "", "render bullet --theme neon", 2, "--theme 'neon'"},
        BadInput{"UnknownOption", "", "render bullet --colour red", 2, "--colour"},
        BadInput{"TraceStepsWithoutValue", "", "trace bullet --steps", 2, "--steps"},
        BadInput{"BadVideoExtension", "", "render bullet --video clip.avi", 2,
                 "must end in .mp4, .webm or .gif"},
        BadInput{"VideoWithoutFfmpeg", "", "render bullet --frames 0:2 --video clip.mp4", 1,
                 "sudo apt-get install ffmpeg"},
        BadInput{"UnwritableOutput", "", "render bullet --frames 0:2 --out blocker/frames", 1,
                 "blocker"},
        BadInput{"FailsHalfWay",
                 R"({"bodies": [{"shape": {"type": "circle", "radius": 1}, "position": [0, 0]}],
                     "events": [{"step": 5, "type": "remove", "body": 0}, {"step": 8, "type": "remove", "body": 0}],
                     "run": {"steps": 20, "frames": "::1"}})",
                 "render bad.json --size 64x64", 2,
                 "bad.json: events[1]: body 0 was already removed before step 8"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST_F(CliTest, AFailedRunKeepsFilesThatExistedBefore) {
  fs::create_directories(dir_ / "out");
  write_file(dir_ / "out/keep.txt", "mine");
  write_file(dir_ / "bad.json",
             R"({"bodies": [{"shape": {"type": "circle", "radius": 1}, "position": [0, 0]}],
      "events": [{"step": 3, "type": "remove", "body": 0}, {"step": 4, "type": "remove", "body": 0}]})");
  const Result result = run("render bad.json --size 64x64 --frames 0:10");
  EXPECT_EQ(result.status, 2);
  EXPECT_EQ(files(), (std::vector<std::string>{"bad.json", "out/keep.txt"}));
}

// Interrupting a render removes everything it created, exits 128 + signal and says so in
// one line; an earlier run's frames of another scene stay as they were.
TEST_F(CliTest, SignalsStopARenderAndRemoveWhatItCreated) {
  for (const auto& [signal, status] : {std::pair<const char*, int>{"TERM", 143}, {"INT", 130},
                                       {"HUP", 129}}) {
    fs::create_directories(dir_ / "frames");
    write_file(dir_ / "frames" / "other_00000.png", "keep");
    const std::string command =
        "cd '" + dir_.string() + "' && ('" IMPULSE2D_CLI "' render tutorial --steps 50000 "
        "--frames ::1 --size 320x240 --out frames/new > out.txt 2> err.txt & pid=$!; sleep 1.5; "
        "kill -" + signal + " $pid; wait $pid; echo $? > status.txt)";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(std::stoi(read_file(dir_ / "status.txt")), status) << signal;
    const std::string err = read_file(dir_ / "err.txt");
    EXPECT_NE(err.find(std::string("impulse2d: interrupted by SIG") + signal), std::string::npos)
        << err;
    EXPECT_NE(err.find("removed the"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir_ / "frames" / "new")) << signal;
    EXPECT_EQ(read_file(dir_ / "frames" / "other_00000.png"), "keep");
    for (const char* name : {"status.txt", "out.txt", "err.txt"}) fs::remove(dir_ / name);
  }
}

// A second render into the same folder refuses to mix its frames with the earlier ones;
// --clean replaces them, and only when the new run succeeded.
TEST_F(CliTest, RerenderingNeedsCleanAndReplacesOnlyOnSuccess) {
  ASSERT_EQ(run("render pyramid --param rows=3 --frames 0:20:10 --size 64x64 --out f").status, 0);
  const std::string first = read_file(dir_ / "f/pyramid_00001.png");
  const Result again = run("render pyramid --param rows=3 --frames 0:20:10 --size 64x64 --out f");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("f/ already holds 3 frames of pyramid"), std::string::npos) << again.err;
  const Result clean =
      run("render pyramid --param rows=3 --frames 0:10:10 --size 80x80 --out f --clean");
  EXPECT_EQ(clean.status, 0) << clean.err;
  EXPECT_EQ(files().size(), 3u);  // the old third frame went with --clean; 2 frames + index
  EXPECT_NE(read_file(dir_ / "f/pyramid_00001.png"), first);
}

// A stale staging directory of a SIGKILLed run (its process is gone) is removed by the next run.
TEST_F(CliTest, StagingLeftByAKilledRunIsRemovedByTheNextRun) {
  fs::create_directories(dir_ / "f" / ".impulse2d-staging-pyramid-999999999");
  write_file(dir_ / "f" / ".impulse2d-staging-pyramid-999999999" / "pyramid_00000.png", "half");
  ASSERT_EQ(run("render pyramid --param rows=3 --frames 0 --size 64x64 --out f").status, 0);
  std::vector<std::string> left = files();
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"f/pyramid_00000.png", "f/pyramid_frames.csv"}));
}
