#pragma once
/// @file task_system.h
/// The caller's threads for a world's step (`WorldSettings::task_system`), in the form of Box2D
/// v3's `enqueueTask` / `finishTask`: the world hands each shared stage to the caller's task
/// system as one task over a number of items, and waits for it. The world's own pool
/// (`WorldSettings::worker_count` without a task system) is the default one.
///
/// Determinism does not depend on the task system: the items the world enqueues are chunks
/// whose bounds it fixed from the counts alone, each chunk's arithmetic is the same on any
/// thread, and every reduction is made afterwards on the calling thread in a fixed order. So
/// the state after every step is bit-identical however the ranges are split, ordered or placed
/// on threads.

namespace impulse2d {

/// A task's work over its items [begin, end) (0 <= begin < end <= the enqueued item count),
/// run by worker `worker_index` (0 <= worker_index < `WorldSettings::worker_count`; two ranges
/// running at the same time must have different indices). `task_context` is the pointer given
/// to `EnqueueTaskFunction`.
using TaskFunction = void (*)(int begin, int end, int worker_index, void* task_context);

/// Starts `task` over the items [0, item_count): the task system must call `task` over
/// contiguous ranges that cover every item exactly once, in any order and from any threads
/// (the calling one included), each range at least `min_range` items long except where fewer
/// are left. It may run them before returning. Returns a handle that `FinishTaskFunction`
/// waits on, or null when every range has already run (then `finish` is not called).
/// `item_count` >= 1; `user_context` is `TaskSystem::user_context`.
using EnqueueTaskFunction = void* (*)(TaskFunction task, int item_count, int min_range,
                                      void* task_context, void* user_context);

/// Returns once every range of the task whose handle `enqueue` returned has run (it may run
/// ranges itself on the calling thread while it waits). Called once per non-null handle, on the
/// thread that enqueued it, before the next task is enqueued.
using FinishTaskFunction = void (*)(void* task_handle, void* user_context);

/// The caller's task system: both functions, or neither. With neither (the default), the world
/// runs shared stages itself: on `worker_count - 1` threads of its own plus the calling one
/// when `worker_count` > 1, else on the calling thread alone. With both, the world starts no
/// threads and gives every shared stage to `enqueue` then `finish`, one task at a time, from
/// the thread that called `World::step`; `worker_count` then says how many workers the system
/// has (the world sizes its chunks by it). After `finish` the world checks that the ranges run
/// were within the items, added up to the item count and had valid worker indices, and throws
/// `Error` naming `task_system` if not (the step is then left half done).
struct TaskSystem {
  EnqueueTaskFunction enqueue = nullptr;  ///< starts a task (null: the world's own workers)
  FinishTaskFunction finish = nullptr;    ///< waits for a task (set exactly when `enqueue` is)
  void* user_context = nullptr;           ///< passed back to both functions, as is
};

}  // namespace impulse2d
