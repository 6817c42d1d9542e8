#pragma once
/// @file dynamic_tree.h
/// A bounding volume hierarchy of boxes that changes incrementally: leaves are inserted where
/// they grow the tree's total perimeter least, removed in constant time plus the walk to the
/// root, and the tree is kept height-balanced by rotations, so a query visits O(log n) nodes
/// plus the ones it finds.

#include "core/shape.h"

#include <array>
#include <cassert>
#include <cstdint>
#include <vector>

namespace impulse2d {

/// A binary tree of axis-aligned boxes whose leaves (proxies) carry a body slot. Inner nodes
/// hold the union of their children. Nodes live in one array with a free list, so once the
/// array has grown to a scene's size, inserting and removing allocate nothing.
class DynamicTree {
 public:
  /// The proxy id returned for "no proxy".
  static constexpr std::int32_t null_node = -1;

  /// Adds a leaf covering `box` (metres; finite) for body slot `slot`; returns its proxy id.
  std::int32_t create_proxy(const Aabb& box, std::uint32_t slot);
  /// Removes the leaf `proxy`; its id may be reused by a later `create_proxy`.
  void destroy_proxy(std::int32_t proxy);
  /// Gives leaf `proxy` the box `box` (metres; finite) and re-inserts it where it now fits best.
  void move_proxy(std::int32_t proxy, const Aabb& box);
  /// The box of leaf `proxy`, metres.
  const Aabb& box(std::int32_t proxy) const { return nodes_[static_cast<std::size_t>(proxy)].box; }
  /// The body slot of leaf `proxy`.
  std::uint32_t slot(std::int32_t proxy) const { return nodes_[static_cast<std::size_t>(proxy)].slot; }

  /// Calls `visit(slot)` for each leaf whose box overlaps or touches `box`, in tree order (not
  /// slot order); stops early when `visit` returns false.
  template <typename Visit>
  void query(const Aabb& box, Visit&& visit) const;
  /// Calls `visit(slot)` for each leaf whose box the segment `origin` -> `origin + translation`
  /// (metres) meets, in tree order; stops early when `visit` returns false.
  template <typename Visit>
  void raycast(vec2 origin, vec2 translation, Visit&& visit) const;

  /// Number of leaves.
  int proxy_count() const { return proxy_count_; }
  /// Edges on the longest path from the root to a leaf (0 for one leaf, -1 when empty).
  int height() const { return root_ == null_node ? -1 : nodes_[static_cast<std::size_t>(root_)].height; }
  /// Checks the structure (for tests): parent links, heights, every inner box the union of its
  /// children, children's heights differing by at most 1, leaf count. True when all hold.
  bool is_valid() const;

 private:
  struct Node {
    Aabb box;                          // leaf: the proxy's box; inner: union of the children
    std::int32_t parent = null_node;   // in the free list: the next free node
    std::int32_t child1 = null_node;   // null for a leaf
    std::int32_t child2 = null_node;
    std::int32_t height = 0;           // 0 for a leaf, -1 for a free node
    std::uint32_t slot = 0;            // leaf: the body slot
    bool is_leaf() const { return child1 == null_node; }
  };
  // Deepest traversal stack a query needs: a height-balanced tree of 2^31 leaves is under 45
  // levels deep (AVL bound 1.44 log2 n), and a depth-first walk keeps at most one pending
  // sibling per level.
  static constexpr int max_stack = 64;

  std::int32_t allocate_node();
  void free_node(std::int32_t node);
  void insert_leaf(std::int32_t leaf);
  void remove_leaf(std::int32_t leaf);
  std::int32_t best_sibling(const Aabb& box) const;
  std::int32_t balance(std::int32_t node);
  std::int32_t rotate_up(std::int32_t node, std::int32_t low, std::int32_t high);
  void refit_upwards(std::int32_t node);
  bool subtree_valid(std::int32_t node, std::int32_t parent, int& leaves) const;
  static bool segment_meets(const Aabb& box, vec2 origin, vec2 translation);

  std::vector<Node> nodes_;
  std::int32_t root_ = null_node;
  std::int32_t free_list_ = null_node;
  int proxy_count_ = 0;
};

template <typename Visit>
void DynamicTree::query(const Aabb& box, Visit&& visit) const {
  if (root_ == null_node) return;
  std::array<std::int32_t, max_stack> stack;
  int size = 0;
  stack[size++] = root_;
  while (size > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--size])];
    if (!node.box.overlaps(box)) continue;
    if (node.is_leaf()) {
      if (!visit(node.slot)) return;
      continue;
    }
    assert(size + 2 <= max_stack);
    stack[size++] = node.child2;
    stack[size++] = node.child1;
  }
}

template <typename Visit>
void DynamicTree::raycast(vec2 origin, vec2 translation, Visit&& visit) const {
  if (root_ == null_node) return;
  std::array<std::int32_t, max_stack> stack;
  int size = 0;
  stack[size++] = root_;
  while (size > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--size])];
    if (!segment_meets(node.box, origin, translation)) continue;
    if (node.is_leaf()) {
      if (!visit(node.slot)) return;
      continue;
    }
    assert(size + 2 <= max_stack);
    stack[size++] = node.child2;
    stack[size++] = node.child1;
  }
}

}  // namespace impulse2d
