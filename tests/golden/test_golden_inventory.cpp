/// @file test_golden_inventory.cpp
/// The golden set and the catalog agree: every built-in scene has goldens, every golden file
/// is used by a test (the catalog's, or the browser viewer's) and has its partner, and each
/// sidecar describes its catalog entry.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "demos/scene_registry.h"
#include "tests/golden/test_golden_support.h"
#include "tests/support/viewer_golden.h"
#include "golden/inventory.h"
#include "golden/sidecar.h"
#include "golden/scenes/golden_catalog.h"

namespace impulse2d::golden {
namespace {

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += "\n  " + name;
  return text;
}

std::vector<std::string> catalog_ids() {
  std::vector<std::string> ids;
  for (const GoldenSpec& spec : golden_catalog()) ids.push_back(spec.id());
  return ids;
}

// docs/golden.md states the catalogue's size; issue 29 found it saying 61 when there were 66.
TEST(GoldenDocs, FiguresMatchTheCatalog) {
  const std::filesystem::path doc =
      std::filesystem::path(IMPULSE2D_GOLDEN_DIR).parent_path() / "docs" / "golden.md";
  std::ifstream file(doc);
  ASSERT_TRUE(file) << doc;
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string figure =
      "The catalogue holds " + std::to_string(golden_catalog().size()) + " built-in goldens";
  EXPECT_NE(text.find(figure), std::string::npos)
      << doc.string() << " should say '" << figure << "' (update the figure with the catalogue)";
}

TEST(GoldenCatalog, CoversEveryBuiltinSceneWithUniqueNames) {
  std::set<std::string> ids;
  std::set<std::string> test_names;
  for (const GoldenSpec& spec : golden_catalog()) {
    EXPECT_NE(demos::find_builtin_scene(spec.scene), nullptr) << spec.id();
    EXPECT_TRUE(ids.insert(spec.id()).second) << "duplicate golden " << spec.id();
    EXPECT_TRUE(test_names.insert(golden_test_name(spec)).second)
        << "duplicate test name " << golden_test_name(spec);
  }
  for (const demos::Scene& scene : demos::builtin_scenes()) {
    for (const char* name : {"start", "motion", "settled", "motion_overlays", "settled_overlays"}) {
      EXPECT_NE(find_golden(scene.name + "/" + name), nullptr)
          << "built-in scene " << scene.name << " has no '" << name << "' golden";
    }
  }
}

TEST(GoldenInventory, EveryGoldenFileIsUsedAndPaired) {
  const GoldenInventory inventory = scan_goldens(testing::golden_dir());
  EXPECT_TRUE(inventory.missing_sidecar.empty())
      << "golden PNGs without a .json sidecar:" << join(inventory.missing_sidecar);
  EXPECT_TRUE(inventory.missing_image.empty())
      << "golden sidecars without a .png:" << join(inventory.missing_image);
  std::vector<std::string> used = catalog_ids();
  used.push_back(impulse2d::testing::kViewerGolden);  // a browser screenshot, not a scene frame
  const std::vector<std::string> unused = unused_goldens(inventory.goldens, used);
  EXPECT_TRUE(unused.empty()) << "goldens no test uses (delete them, or add them to "
                                 "golden/scenes/golden_catalog.cpp):"
                              << join(unused);
}

TEST(GoldenInventory, SidecarsDescribeTheirCatalogEntry) {
  for (const GoldenSpec& spec : golden_catalog()) {
    const std::filesystem::path file =
        sidecar_path_for(golden_png_path(testing::golden_dir(), spec.id()));
    if (!std::filesystem::exists(file)) continue;  // the golden's own test reports it missing
    const Sidecar sidecar = read_sidecar(file, spec.id() + ".json");
    EXPECT_EQ(sidecar.scene, spec.scene) << spec.id();
    EXPECT_EQ(sidecar.frame, spec.step) << spec.id();
    EXPECT_EQ(sidecar.width, kGoldenWidth) << spec.id();
    EXPECT_EQ(sidecar.height, kGoldenHeight) << spec.id();
  }
}

}  // namespace
}  // namespace impulse2d::golden
