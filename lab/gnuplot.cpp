/// @file gnuplot.cpp
#include "lab/gnuplot.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impulse2d::lab {

bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

void run_gnuplot(const std::string& script, const std::string& png_path) {
  const std::filesystem::path target(png_path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string temporary_png = png_path + ".tmp.png";
  const std::string script_path = png_path + ".gp.tmp";
  const std::string log_path = png_path + ".log.tmp";
  std::string text = script;
  const std::string placeholder = "OUTPUT";
  for (std::size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at + temporary_png.size())) {
    text.replace(at, placeholder.size(), "'" + temporary_png + "'");
  }
  {
    std::ofstream file(script_path, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + script_path);
    file << text;
  }
  const std::string command = "gnuplot '" + script_path + "' >'" + log_path + "' 2>&1";
  const int status = std::system(command.c_str());
  std::ostringstream log;
  if (std::ifstream file(log_path); file) log << file.rdbuf();
  std::error_code ignored;
  std::filesystem::remove(script_path, ignored);
  std::filesystem::remove(log_path, ignored);
  if (status != 0 || !std::filesystem::exists(temporary_png)) {
    std::filesystem::remove(temporary_png, ignored);
    throw std::runtime_error("gnuplot failed drawing " + png_path + ": " + log.str());
  }
  std::filesystem::rename(temporary_png, target);
}

std::string gnuplot_text(const std::string& text) {
  std::string result;
  for (const char c : text) {
    if (c == '"' || c == '\\') result += '\\';
    result += c;
  }
  return result;
}

}  // namespace impulse2d::lab
