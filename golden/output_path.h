#pragma once
/// @file output_path.h
/// The files and folders a golden command will write, checked before any work: a run that
/// would fail at its last write (an unwritable --junit) must fail before it renders or
/// changes anything.

#include <filesystem>
#include <string>

namespace impulse2d::golden {

/// Checks that `path` can be written as a file (`folder` false) or a folder: it is not the
/// other kind, and its nearest existing ancestor is a writable folder (missing folders
/// between are created by the write). `option` names it in errors, e.g. "--junit".
/// Throws `GoldenError` "<option> <path>: <reason>".
void check_output_path(const std::filesystem::path& path, const std::string& option, bool folder);

}  // namespace impulse2d::golden
