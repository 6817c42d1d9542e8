#include "tests/support/test_render_support.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

extern char** environ;

namespace impulse2d::render::testing {

Pixel to_pixel(Color color) {
  const auto byte = [](float channel) {
    return static_cast<std::uint8_t>(std::lround(std::min(std::max(channel, 0.0f), 1.0f) * 255.0f));
  };
  return Pixel{byte(color.r), byte(color.g), byte(color.b), 255};
}

World make_overlay_scene(int steps) {
  WorldSettings settings;
  settings.enable_sleeping = false;
  World world(settings);

  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0.0f, -0.5f};
  world.create_body(ground, make_box({8.0f, 0.5f}));

  // A two-box stack (resting contacts, normal impulses, penetration).
  for (int i = 0; i < 2; ++i) {
    BodyDef box;
    box.position = {-4.0f, 0.5f + 1.0f * static_cast<float>(i)};
    world.create_body(box, make_oriented_box({0.5f, 0.5f}));
  }
  // A box sliding to the right (friction impulses, a velocity arrow).
  BodyDef slider;
  slider.position = {-1.0f, 0.4f};
  slider.linear_velocity = {6.0f, 0.0f};
  slider.material.static_friction = 0.3f;
  slider.material.dynamic_friction = 0.2f;
  world.create_body(slider, make_box({0.6f, 0.4f}));
  // A circle dropped from above.
  BodyDef ball;
  ball.position = {3.0f, 3.0f};
  ball.angular_velocity = 1.0f;
  world.create_body(ball, make_circle(0.6f));
  // A triangle put to sleep on the ground.
  const vec2 triangle[3] = {{5.0f, 0.0f}, {6.5f, 0.0f}, {5.7f, 1.2f}};
  vec2 centroid;
  const Shape shape = make_polygon(triangle, 3, &centroid);
  BodyDef sleeper;
  sleeper.position = centroid;
  const BodyId sleeping = world.create_body(sleeper, shape);

  for (int i = 0; i < steps; ++i) world.step();
  world.set_awake(sleeping, false);
  return world;
}

int run_self(const std::string& test_filter, const std::map<std::string, std::string>& variables) {
  std::vector<std::string> environment;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string text(*entry);
    const std::string name = text.substr(0, text.find('='));
    if (variables.count(name) == 0) environment.push_back(text);
  }
  for (const auto& [name, value] : variables) environment.push_back(name + "=" + value);
  std::vector<char*> envp;
  for (std::string& text : environment) envp.push_back(text.data());
  envp.push_back(nullptr);

  std::string program = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string filter = "--gtest_filter=" + test_filter;
  char* argv[] = {program.data(), filter.data(), nullptr};
  pid_t child = 0;
  if (posix_spawn(&child, program.c_str(), nullptr, nullptr, argv, envp.data()) != 0) return -1;
  int status = 0;
  if (waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::uint8_t> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string make_temporary_directory(const std::string& tag) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("impulse2d-" + tag + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) return std::string();
  return pattern;
}

}  // namespace impulse2d::render::testing
