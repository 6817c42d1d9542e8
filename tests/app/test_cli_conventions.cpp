// Command-line conventions of the impulse2d program (issue 15.5): -o/--out for output
// everywhere, --param one pair per flag, --version, --quiet, every error prefixed
// `impulse2d:` with a "did you mean" for a misspelling, one set of exit statuses per command,
// trace defaulting to the scene's length, overlay meanings in --help.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "tests/support/cli_test_support.h"

using namespace cli_test;

namespace {

/// A JSON scene whose run is 7 steps long.
const char* const short_run = R"({
  "bodies": [{"shape": {"type": "circle", "radius": 0.25}, "position": [0, 10]}],
  "run": {"steps": 7, "frames": "0:7:1"}
})";

/// True when every line of `text` starts with one of the program's own prefixes.
bool every_line_is_ours(const std::string& text) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("impulse2d:", 0) != 0 && line.rfind("Run 'impulse2d ", 0) != 0) return false;
  }
  return !text.empty();
}

struct Misuse {
  const char* name;
  const char* arguments;
  const char* message;  // the first line of stderr starts with it
};

class CliMisuse : public CliTest, public ::testing::WithParamInterface<Misuse> {};

}  // namespace

TEST_P(CliMisuse, IsBadUsageInTheProgramsOwnWordsWithASuggestion) {
  const Misuse& misuse = GetParam();
  const Result result = run(misuse.arguments);
  EXPECT_EQ(result.status, 2) << result.err;
  EXPECT_EQ(result.err.rfind(misuse.message, 0), 0u) << "stderr: " << result.err;
  EXPECT_TRUE(every_line_is_ours(result.err)) << "stderr: " << result.err;
  EXPECT_EQ(result.out, "");
  EXPECT_TRUE(files().empty());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliMisuse,
    ::testing::Values(
        Misuse{"MisspeltCommand", "rendr pyramid",
               "impulse2d: unknown command 'rendr' (did you mean 'render'?)"},
        Misuse{"UnknownCommand", "explode", "impulse2d: unknown command 'explode'\n"},
        Misuse{"MisspeltSubcommand", "golden chek a.json",
               "impulse2d: golden: unknown command 'chek' (did you mean 'check'?)"},
        Misuse{"MissingSubcommand", "golden",
               "impulse2d: golden: a command is required: check, update, frame"},
        Misuse{"MisspeltOption", "render pyramid --sise 64x64",
               "impulse2d: render: unknown option '--sise' (did you mean '--size'?)"},
        Misuse{"MisspeltOptionWithValue", "sheet pyramid --colums=3",
               "impulse2d: sheet: unknown option '--colums' (did you mean '--columns'?)"},
        Misuse{"UnexpectedArgument", "render pyramid extra",
               "impulse2d: render: unexpected argument 'extra'"},
        Misuse{"MissingScene", "render", "impulse2d: render: scene is required"},
        Misuse{"MissingValue", "render pyramid --size", "impulse2d: render: "},
        Misuse{"BadNumber", "sheet pyramid --count many", "impulse2d: sheet: "},
        Misuse{"NoFramesWithoutVideo", "render pyramid --no-frames",
               "impulse2d: --no-frames needs --video FILE"},
        Misuse{"OutputNamedLikeAVideo", "render pyramid -o out.mp4",
               "impulse2d: render: --out: -o names the folder of the PNG frames, not a video: "
               "write --video out.mp4 (with --no-frames for the video alone)\n"},
        Misuse{"OutputNamedLikeAVideoInADryRun", "render pyramid -o clip.gif --dry-run",
               "impulse2d: render: --out: -o names the folder of the PNG frames, not a video: "
               "write --video clip.gif"},
        Misuse{"FpsWithoutVideo", "render pyramid --fps 30",
               "impulse2d: --fps sets the video's rate: it needs --video FILE"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST_F(CliTest, VersionPrintsTheProgramVersion) {
  for (const char* arguments : {"--version", "-V", "render --version", "render -V"}) {
    const Result result = run(arguments);
    EXPECT_EQ(result.status, 0) << arguments << result.err;
    EXPECT_EQ(result.out.rfind("impulse2d ", 0), 0u) << result.out;
    EXPECT_NE(result.out.find('.'), std::string::npos) << result.out;  // "impulse2d 0.1.0"
  }
}

TEST_F(CliTest, HelpCommandIsTheHelpFlag) {
  const Result program = run("help");
  EXPECT_EQ(program.status, 0) << program.err;
  EXPECT_EQ(program.out, run("--help").out);
  EXPECT_NE(program.out.find("impulse2d help COMMAND"), std::string::npos) << program.out;
  const Result render = run("help render");
  EXPECT_EQ(render.status, 0) << render.err;
  EXPECT_EQ(render.out, run("render --help").out);
  EXPECT_NE(render.out.find("Usage: impulse2d render"), std::string::npos) << render.out;

  const Result unknown = run("help rendr");
  EXPECT_EQ(unknown.status, 2);
  EXPECT_EQ(unknown.err, "impulse2d: help: unknown command 'rendr' (commands: list, render, "
                         "trace, sheet, diff, golden, lab, tune)\n");
  const Result two = run("help render sheet");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("one command at most"), std::string::npos) << two.err;
}

// A reader that stops early (`impulse2d list | head -1`) is no error: no message, and the
// status of a program ended by SIGPIPE (141), as GNU tools; 0 when the output fit in the pipe
// before the reader closed it.
TEST_F(CliTest, ClosedPipeEndsQuietly) {
  const std::string command = "cd '" + dir_.string() + "' && bash -c \"( '" IMPULSE2D_CLI
                              "' list 2> err.txt; echo \\$? > status.txt ) | "
                              "(exec 0<&-; sleep 0.3)\"";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string status = read_file(dir_ / "status.txt");
  EXPECT_TRUE(status == "141\n" || status == "0\n") << status;
  EXPECT_EQ(read_file(dir_ / "err.txt"), "");
}

TEST_F(CliTest, QuietPrintsNothingOnSuccess) {
  for (const char* arguments :
       {"--quiet render pyramid -p rows=3 --frames 0:10:5 --size 64x64 -o a",
        "render pyramid -p rows=3 --frames 0:10:5 --size 64x64 -o b -q",
        "sheet pyramid -p rows=3 --count 2 --tile 64x48 -o s.png --quiet",
        "lab --quick --only projectile --no-stability --no-charts --no-peers --repeats 1 -o l -q"}) {
    const Result result = run(arguments);
    EXPECT_EQ(result.status, 0) << arguments << result.err;
    EXPECT_EQ(result.out, "") << arguments;
    EXPECT_EQ(result.err, "") << arguments;
  }
  EXPECT_TRUE(fs::exists(dir_ / "a/pyramid_00002.png"));
  EXPECT_TRUE(fs::exists(dir_ / "b/pyramid_00002.png"));
  EXPECT_TRUE(fs::exists(dir_ / "s.png"));
  EXPECT_TRUE(fs::exists(dir_ / "l/lab.csv"));
}

// -o is the output everywhere (it used to be --overlays, so `sheet stack -o sheet.png` failed).
TEST_F(CliTest, DashOIsTheOutputOfEveryCommand) {
  ASSERT_EQ(run("sheet pyramid -p rows=3 --count 2 --tile 64x48 -o sheet.png").status, 0);
  EXPECT_EQ(read_file(dir_ / "sheet.png").substr(1, 3), "PNG");
  ASSERT_EQ(run("render pyramid -p rows=3 --frames 0,20 --size 64x64 -o f").status, 0);
  const Result diff = run("diff f/pyramid_00000.png f/pyramid_00001.png -o report");
  EXPECT_EQ(diff.status, 1) << diff.err;
  EXPECT_TRUE(fs::exists(dir_ / "report/index.html"));
  const Result overlays = run("render pyramid --frames 0 --size 64x64 -o g --overlays normals");
  EXPECT_EQ(overlays.status, 0) << overlays.err;
}

// --param takes one pair per flag: it no longer swallows the scene name after it.
TEST_F(CliTest, ParamTakesOnePairPerFlag) {
  const Result before = run("render --param rows=3 pyramid --frames 0 --size 64x64 -o f");
  EXPECT_EQ(before.status, 0) << before.err;
  EXPECT_TRUE(fs::exists(dir_ / "f/pyramid_00000.png"));
  const Result repeated =
      run("sheet -p rows=3 ball_pit -p seed=2 -p rows=4 --count 1 --tile 64x48 -o s.png");
  EXPECT_EQ(repeated.status, 2);  // ball_pit has no rows: the pairs reached the scene one by one
  EXPECT_NE(repeated.err.find("unknown parameter 'rows'"), std::string::npos) << repeated.err;
  const Result two = run("render -p rows=3 -p rows=4 pyramid --frames 0 --size 64x64 -o g");
  EXPECT_EQ(two.status, 0) << two.err;
}

TEST_F(CliTest, TraceDefaultsToTheScenesLength) {
  write_file(dir_ / "short.json", short_run);
  const Result result = run("trace short.json");
  ASSERT_EQ(result.status, 0) << result.err;
  std::istringstream lines(result.out);
  std::string line, last;
  int rows = -1;  // the header
  while (std::getline(lines, line)) {
    last = line;
    ++rows;
  }
  EXPECT_EQ(rows, 8);  // steps 0..7
  EXPECT_EQ(last.rfind("7,", 0), 0u) << last;
}

TEST_F(CliTest, HelpStatesOneSetOfExitStatusesPerCommand) {
  const Result diff = run("diff --help");
  ASSERT_EQ(diff.status, 0);
  EXPECT_NE(diff.out.find("0 the frames match, 1 they differ, 2 trouble"), std::string::npos)
      << diff.out;
  EXPECT_EQ(diff.out.find("runtime failure"), std::string::npos) << diff.out;
  for (const char* command : {"", "render ", "sheet ", "trace ", "golden "}) {
    const Result help = run(std::string(command) + "--help");
    EXPECT_NE(help.out.find("Exit status: 0 success; 1 runtime failure"), std::string::npos)
        << command << help.out;
  }
}

// Every help text fits a 100-column terminal: the program's, each command's (`help X`) and
// each subcommand's (`X Y --help`), golden's and lab's included.
TEST_F(CliTest, EveryHelpLineFitsInOneHundredColumns) {
  for (const char* arguments :
       {"help", "help list", "help render", "help trace", "help sheet", "help diff", "help golden",
        "help lab", "help tune", "golden check --help", "golden update --help",
        "golden frame --help", "lab merge --help"}) {
    const Result help = run(arguments);
    EXPECT_EQ(help.status, 0) << arguments << help.err;
    std::istringstream lines(help.out);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
      ++number;
      EXPECT_LE(line.size(), 100u) << arguments << ", line " << number << ": " << line;
    }
    EXPECT_GT(number, 3) << arguments << ": no help printed";
  }
}

TEST_F(CliTest, HelpSaysWhatEachOverlayShows) {
  for (const char* command : {"render", "sheet"}) {
    const Result help = run(std::string(command) + " --help");
    EXPECT_NE(help.out.find("normals: contact normals"), std::string::npos) << help.out;
    EXPECT_NE(help.out.find("penetration: penetration depth"), std::string::npos) << help.out;
  }
}

// --dry-run checks a command line (the docs test runs every README command with it), prints
// the plan and writes nothing.
TEST_F(CliTest, DryRunChecksTheCommandLineAndWritesNothing) {
  for (const char* arguments :
       {"--dry-run render pyramid -p rows=20 --frames 0:600:10 -o out/pyramid",
        "sheet tutorial --frames 0:900:128 -o docs/sheet.png --dry-run", "--dry-run trace bullet",
        "--dry-run lab --quick", "--dry-run"}) {
    const Result result = run(arguments);
    EXPECT_EQ(result.status, 0) << arguments << result.err;
    EXPECT_EQ(result.err, "") << arguments;
    EXPECT_NE(result.out, "") << arguments << ": no plan printed";
  }
  const Result plan = run("--dry-run render pyramid -p rows=20 --frames 0:600:10 -o out/pyramid");
  for (const char* line : {"dry run: render pyramid", "parameters: rows=20",
                           "frames: 61: steps 0, 10, .. 600 (every 10)", "frame size: 800x600",
                           "out/pyramid/pyramid_00000.png .. out/pyramid/pyramid_00060.png",
                           "out/pyramid/pyramid_frames.csv", "nothing was run or written"}) {
    EXPECT_NE(plan.out.find(line), std::string::npos) << line << " not in: " << plan.out;
  }
  EXPECT_TRUE(files().empty());
  const Result frames = run("--dry-run render bullet --frames 0:500");
  EXPECT_EQ(frames.status, 2);
  EXPECT_NE(frames.err.find("after the end of the run"), std::string::npos) << frames.err;
  const Result param = run("--dry-run sheet pyramid -p cols=3");
  EXPECT_EQ(param.status, 2);
  EXPECT_NE(param.err.find("unknown parameter 'cols'"), std::string::npos) << param.err;
  EXPECT_EQ(run("--dry-run lab --quikc").status, 2);
  EXPECT_TRUE(files().empty());
}

TEST_F(CliTest, ErrorsOfDiffAndGoldenArePrefixedToo) {
  const Result diff = run("diff nowhere.png other.png");
  EXPECT_EQ(diff.status, 2);
  EXPECT_EQ(diff.err.rfind("impulse2d: diff: ", 0), 0u) << diff.err;
  const Result golden = run("golden check nowhere.json");
  EXPECT_EQ(golden.status, 2);
  EXPECT_EQ(golden.err.rfind("impulse2d: golden: ", 0), 0u) << golden.err;
}
