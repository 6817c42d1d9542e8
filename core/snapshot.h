#pragma once
/// @file snapshot.h
/// Saving a world's whole state to bytes and restoring it (`World::save_snapshot`,
/// `World::restore_snapshot`): a restored world continues bit for bit as the original (for
/// rollback netcode, replays, bug reports).
///
/// Layout (version 4), every number little-endian, floats as their IEEE-754 bits:
///   header   u32 magic 'I2DS' (0x53443249), u32 version (4), u64 payload byte count,
///            u64 FNV-1a 64 hash of the payload
///   payload  sections in this order, each a u32 tag then its fields:
///     'SETT' WorldSettings, every field in declaration order (enums as u32, bools as u8)
///     'TIME' f64 time, i64 step count, f32 accumulator, u8 bounds current
///     'BODY' u32 slot count; per slot: u8 alive, then Body's fields in declaration order
///            (shape: u8 kind + circle radius | box half extents | polygon count, 8 vertices,
///            8 normals, radius, rounding | capsule centre 1, centre 2, radius | segment point
///            1, point 2, u8 one-sided, ghost 1, ghost 2; material: u32 name length, name bytes, 4 floats;
///            then u8 compound, u32 shape count and per shape: shape, transform, material,
///            u32 layers), u32 free
///            slot count + slots, i32 living count
///     'JOIN' u32 slot count; per slot: u8 alive + Joint's fields; free slots; living count
///     'CONT' awake contacts, then 'SLEE' sleeping contacts: u32 count + each Contact's fields,
///            points included (shape indices as u32; warm-start impulses, friction and
///            bounce state)
///     'EVNT' hit threshold, event body counts, touching pairs and sensor overlaps (6 u32 each: 2 handles, 2 shape indices),
///            pending end pairs
///   The broad phase is not saved: it is rebuilt from the bodies' bounds in slot order; its
///   pairs never depend on the trees' shape, so the step does not either. The contact filter
///   (a function) is not saved: the restoring world keeps its own. Scratch buffers are not
///   saved.
///
/// Versions 1 (before capsules, segments and rounded polygons), 2 (before chain links) and 3
/// (before compound bodies) are refused like any other.
/// A buffer from another version, truncated, or with any byte changed is refused with an
/// `Error` saying what is wrong (the payload hash catches changed bytes), never a crash.

#include <cstdint>

namespace impulse2d {

/// Magic number at the start of every snapshot ("I2DS" in memory order).
constexpr std::uint32_t snapshot_magic = 0x53443249u;
/// The layout version this build writes and reads.
constexpr std::uint32_t snapshot_version = 4u;

}  // namespace impulse2d
