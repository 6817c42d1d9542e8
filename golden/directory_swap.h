#pragma once
/// @file directory_swap.h
/// A directory built beside its place, moved into place in one step: a reader sees the old
/// directory or the new one, never a mix (the golden update's scene folders, the report).

#include <filesystem>

namespace impulse2d::golden {

/// Moves `staged` to `target` (same filesystem). When `target` exists, the two are exchanged
/// atomically (Linux `renameat2(RENAME_EXCHANGE)`; where the filesystem lacks it, `target` is
/// first renamed to `staged` + ".old" and then `staged` into place), so `staged` (or its
/// ".old" sibling) holds the old directory afterwards; returns that path, or an empty path
/// when there was no `target`. Throws `GoldenError` naming both paths and the system's reason.
std::filesystem::path swap_directory_into_place(const std::filesystem::path& staged,
                                                const std::filesystem::path& target);

}  // namespace impulse2d::golden
