// libFuzzer target: any bytes as a scene file. The loader must either reject them with
// UsageError (a clear message) or give a scene whose world builds and steps 60 times without
// a crash, a sanitizer report or an exception other than the documented ones.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "scene/params.h"
#include "scene/scene_loader.h"
#include "scene/scene_run.h"
#include "scene/usage_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impulse2d;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const demos::Scene scene = demos::parse_scene(text, "fuzz.json");
    demos::SceneRun run(scene, demos::Params(scene.params));
    for (int step = 0; step < 60; ++step) run.step();
  } catch (const demos::UsageError&) {
    // rejected with a message: fine
  } catch (const Error&) {
    // the core refused a definition the loader let through: fine, it names the field
  }
  return 0;
}
