#include "core/collide/dynamic_tree.h"

#include <algorithm>
#include <cstdlib>

namespace impulse2d {

namespace {

Aabb unite(const Aabb& a, const Aabb& b) {
  return Aabb{glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)};
}

// Half the perimeter's weight is enough to compare insertion costs; the full perimeter keeps
// the numbers readable (metres).
float perimeter(const Aabb& box) {
  return 2.0f * ((box.upper.x - box.lower.x) + (box.upper.y - box.lower.y));
}

}  // namespace

std::int32_t DynamicTree::allocate_node() {
  if (free_list_ == null_node) {
    nodes_.emplace_back();
    return static_cast<std::int32_t>(nodes_.size() - 1);
  }
  const std::int32_t node = free_list_;
  free_list_ = nodes_[static_cast<std::size_t>(node)].parent;
  nodes_[static_cast<std::size_t>(node)] = Node{};
  return node;
}

void DynamicTree::free_node(std::int32_t node) {
  Node& freed = nodes_[static_cast<std::size_t>(node)];
  freed.parent = free_list_;
  freed.child1 = null_node;
  freed.child2 = null_node;
  freed.height = -1;
  free_list_ = node;
}

std::int32_t DynamicTree::create_proxy(const Aabb& box, std::uint32_t slot) {
  const std::int32_t leaf = allocate_node();
  Node& node = nodes_[static_cast<std::size_t>(leaf)];
  node.box = box;
  node.slot = slot;
  node.height = 0;
  insert_leaf(leaf);
  ++proxy_count_;
  return leaf;
}

void DynamicTree::destroy_proxy(std::int32_t proxy) {
  assert(nodes_[static_cast<std::size_t>(proxy)].is_leaf());
  remove_leaf(proxy);
  free_node(proxy);
  --proxy_count_;
}

void DynamicTree::move_proxy(std::int32_t proxy, const Aabb& box) {
  assert(nodes_[static_cast<std::size_t>(proxy)].is_leaf());
  remove_leaf(proxy);
  nodes_[static_cast<std::size_t>(proxy)].box = box;
  insert_leaf(proxy);
}

// Greedy descent by the surface-area heuristic (perimeter in 2D): at each inner node, compare
// the cost of pairing the new leaf with the node itself against the least cost of going down
// into either child, where going down also pays for growing every ancestor passed on the way.
std::int32_t DynamicTree::best_sibling(const Aabb& box) const {
  std::int32_t index = root_;
  while (!nodes_[static_cast<std::size_t>(index)].is_leaf()) {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    const float area = perimeter(node.box);
    const float combined = perimeter(unite(node.box, box));
    const float cost_here = 2.0f * combined;            // a new parent of this node and the leaf
    const float inherited = 2.0f * (combined - area);   // this node grows if we go below it
    auto cost_below = [&](std::int32_t child_index) {
      const Node& child = nodes_[static_cast<std::size_t>(child_index)];
      const float grown = perimeter(unite(child.box, box));
      return child.is_leaf() ? grown + inherited : grown - perimeter(child.box) + inherited;
    };
    const float cost1 = cost_below(node.child1);
    const float cost2 = cost_below(node.child2);
    if (cost_here < cost1 && cost_here < cost2) break;
    index = cost1 < cost2 ? node.child1 : node.child2;
  }
  return index;
}

void DynamicTree::insert_leaf(std::int32_t leaf) {
  if (root_ == null_node) {
    root_ = leaf;
    nodes_[static_cast<std::size_t>(leaf)].parent = null_node;
    return;
  }
  const std::int32_t sibling = best_sibling(nodes_[static_cast<std::size_t>(leaf)].box);
  const std::int32_t new_parent = allocate_node();  // may move nodes_: no references across it
  Node& sibling_node = nodes_[static_cast<std::size_t>(sibling)];
  const std::int32_t old_parent = sibling_node.parent;
  Node& parent = nodes_[static_cast<std::size_t>(new_parent)];
  parent.box = unite(sibling_node.box, nodes_[static_cast<std::size_t>(leaf)].box);
  parent.parent = old_parent;
  parent.child1 = sibling;
  parent.child2 = leaf;
  parent.height = sibling_node.height + 1;
  sibling_node.parent = new_parent;
  nodes_[static_cast<std::size_t>(leaf)].parent = new_parent;
  if (old_parent == null_node) {
    root_ = new_parent;
  } else {
    Node& grand = nodes_[static_cast<std::size_t>(old_parent)];
    (grand.child1 == sibling ? grand.child1 : grand.child2) = new_parent;
  }
  refit_upwards(old_parent);
}

void DynamicTree::remove_leaf(std::int32_t leaf) {
  if (leaf == root_) {
    root_ = null_node;
    return;
  }
  const std::int32_t parent = nodes_[static_cast<std::size_t>(leaf)].parent;
  const Node& parent_node = nodes_[static_cast<std::size_t>(parent)];
  const std::int32_t grand = parent_node.parent;
  const std::int32_t sibling = parent_node.child1 == leaf ? parent_node.child2 : parent_node.child1;
  nodes_[static_cast<std::size_t>(sibling)].parent = grand;
  if (grand == null_node) {
    root_ = sibling;
  } else {
    Node& grand_node = nodes_[static_cast<std::size_t>(grand)];
    (grand_node.child1 == parent ? grand_node.child1 : grand_node.child2) = sibling;
  }
  free_node(parent);
  refit_upwards(grand);
}

void DynamicTree::refit_upwards(std::int32_t node) {
  while (node != null_node) {
    node = balance(node);
    Node& current = nodes_[static_cast<std::size_t>(node)];
    const Node& first = nodes_[static_cast<std::size_t>(current.child1)];
    const Node& second = nodes_[static_cast<std::size_t>(current.child2)];
    current.box = unite(first.box, second.box);
    current.height = 1 + std::max(first.height, second.height);
    node = current.parent;
  }
}

// If one child of `node` is more than one level taller than the other, lifts the taller child
// into `node`'s place. Returns the subtree's root afterwards.
std::int32_t DynamicTree::balance(std::int32_t node) {
  const Node& current = nodes_[static_cast<std::size_t>(node)];
  if (current.is_leaf() || current.height < 2) return node;
  const int difference = nodes_[static_cast<std::size_t>(current.child2)].height -
                         nodes_[static_cast<std::size_t>(current.child1)].height;
  if (difference > 1) return rotate_up(node, current.child1, current.child2);
  if (difference < -1) return rotate_up(node, current.child2, current.child1);
  return node;
}

// `high` (the taller child of `node`) takes `node`'s place; `node` becomes high's first child
// and keeps `low` plus the shorter of high's children; high keeps its taller child.
std::int32_t DynamicTree::rotate_up(std::int32_t node, std::int32_t low, std::int32_t high) {
  Node& old_top = nodes_[static_cast<std::size_t>(node)];
  Node& new_top = nodes_[static_cast<std::size_t>(high)];
  const std::int32_t first = new_top.child1;
  const std::int32_t second = new_top.child2;
  const bool first_taller = nodes_[static_cast<std::size_t>(first)].height >
                            nodes_[static_cast<std::size_t>(second)].height;
  const std::int32_t keep = first_taller ? first : second;
  const std::int32_t give = first_taller ? second : first;

  const std::int32_t above = old_top.parent;
  new_top.parent = above;
  if (above == null_node) {
    root_ = high;
  } else {
    Node& above_node = nodes_[static_cast<std::size_t>(above)];
    (above_node.child1 == node ? above_node.child1 : above_node.child2) = high;
  }
  new_top.child1 = node;
  new_top.child2 = keep;
  old_top.parent = high;
  (old_top.child1 == high ? old_top.child1 : old_top.child2) = give;
  nodes_[static_cast<std::size_t>(give)].parent = node;

  const Node& low_node = nodes_[static_cast<std::size_t>(low)];
  const Node& give_node = nodes_[static_cast<std::size_t>(give)];
  old_top.box = unite(low_node.box, give_node.box);
  old_top.height = 1 + std::max(low_node.height, give_node.height);
  const Node& keep_node = nodes_[static_cast<std::size_t>(keep)];
  new_top.box = unite(old_top.box, keep_node.box);
  new_top.height = 1 + std::max(old_top.height, keep_node.height);
  return high;
}

// Slab test of the segment against the box, fractions clipped to [0, 1]. Conservative: a
// rounding-made NaN fraction never rejects.
bool DynamicTree::segment_meets(const Aabb& box, vec2 origin, vec2 translation) {
  float enter = 0.0f;
  float leave = 1.0f;
  for (int axis = 0; axis < 2; ++axis) {
    const float start = origin[axis];
    const float delta = translation[axis];
    if (delta == 0.0f) {
      if (start < box.lower[axis] || start > box.upper[axis]) return false;
      continue;
    }
    float near = (box.lower[axis] - start) / delta;
    float far = (box.upper[axis] - start) / delta;
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    leave = std::min(leave, far);
    if (enter > leave) return false;
  }
  return true;
}

bool DynamicTree::subtree_valid(std::int32_t node, std::int32_t parent, int& leaves) const {
  const Node& current = nodes_[static_cast<std::size_t>(node)];
  if (current.parent != parent || current.height < 0) return false;
  if (current.is_leaf()) {
    ++leaves;
    return current.height == 0 && current.child2 == null_node;
  }
  if (current.child2 == null_node) return false;
  if (!subtree_valid(current.child1, node, leaves) || !subtree_valid(current.child2, node, leaves)) {
    return false;
  }
  const Node& first = nodes_[static_cast<std::size_t>(current.child1)];
  const Node& second = nodes_[static_cast<std::size_t>(current.child2)];
  const Aabb united = unite(first.box, second.box);
  return current.height == 1 + std::max(first.height, second.height) &&
         std::abs(first.height - second.height) <= 1 && united.lower == current.box.lower &&
         united.upper == current.box.upper;
}

bool DynamicTree::is_valid() const {
  int leaves = 0;
  if (root_ != null_node && !subtree_valid(root_, null_node, leaves)) return false;
  int free_count = 0;
  for (std::int32_t node = free_list_; node != null_node;
       node = nodes_[static_cast<std::size_t>(node)].parent) {
    if (nodes_[static_cast<std::size_t>(node)].height != -1) return false;
    ++free_count;
  }
  const int in_tree = leaves == 0 ? 0 : 2 * leaves - 1;
  return leaves == proxy_count_ && in_tree + free_count == static_cast<int>(nodes_.size());
}

}  // namespace impulse2d
