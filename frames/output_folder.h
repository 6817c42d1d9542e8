#pragma once
/// @file output_folder.h
/// The check, before any work, that an output folder can be used: it is a folder this process
/// may write into, or the missing folders up to it can be created.

#include <filesystem>
#include <string>

namespace impulse2d::demos {

/// Throws `std::runtime_error` "<where>: cannot use F as a folder: ..." when `folder` exists
/// but is not a writable folder, or is missing and its nearest existing parent F is not a
/// writable folder; `where` names the option and its value ("--out a/b"). Creates nothing.
/// An empty `folder` is the current folder.
void check_output_folder(const std::filesystem::path& folder, const std::string& where);

}  // namespace impulse2d::demos
