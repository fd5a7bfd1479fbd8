// Scene files: TOML (https://toml.io), read with toml++ (Debian libtomlplusplus-dev).
// Why TOML and not JSON: a scene is written by hand, and TOML has comments (units and reasons go
// beside each value), typed numbers, arrays of tables for repeated items ([[material]], [[wall]])
// and no quoting noise; toml++ keeps the line of every value, so errors can name it. JSON has no
// comments, and nlohmann-json keeps no positions.
//
// The parser lives in one host-only translation unit (src/scene_toml.cpp, compiled by g++ in both
// builds: nvcc cannot compile toml++), so this header has no TOML in it. README.md documents the
// format with a complete annotated example (data/scenes/drop.toml).
#pragma once
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>
#include "blaze/scene/scene.hpp"

namespace blaze {

// Reads and validates a scene file. `overrides` are "key=value" strings from the command line
// (--set simulation.dt=1e-5, or --set dt=1e-5 for keys of [simulation] and [output]); the value
// is TOML (numbers, strings in quotes or bare words, [x, y, z] arrays). Relative shape paths are
// taken from the working directory. Throws SceneError naming file, line, key, value and what is
// allowed.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for scene text already in memory (`name` stands for the file in messages).
Scene parse_scene(const std::string& text, const std::string& name, const std::vector<std::string>& overrides = {});

// Creates the run's output directory ([output] directory, with `sub` inside it when given) and
// returns its path. One that cannot be made (a file where a folder of the path should be, no
// permission) is a SceneError naming output.directory, the path and why, before any file is written.
inline std::string make_output_directory(const Scene& s, const std::string& sub = "") {
  const std::string dir = sub.empty() ? s.output.directory : s.output.directory + "/" + sub;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!ec && !std::filesystem::is_directory(dir, ec) && !ec) ec = std::make_error_code(std::errc::not_a_directory);
  if (ec)
    throw SceneError(s.place("output.directory") + " = \"" + s.output.directory + "\": cannot create the folder " + dir + ": " +
                     ec.message() + "; give a folder that can be made here");
  return dir;
}

}  // namespace blaze
