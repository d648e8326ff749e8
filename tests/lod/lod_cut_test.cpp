// SPDX-License-Identifier: Apache-2.0
// The level-of-detail cut (lib/lod/lod_cut.h): its invariants (no node with an
// ancestor, every visible leaf covered exactly once, diffs that replay to the cut,
// priorities = eye-to-centre distances, more detail when nearer, the node cap), culling,
// hysteresis, re-prioritization, reset/full and option checks.
#include "lod/lod_cut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "lod/camera_path.h"
#include "lod/lod_test_grids.h"
#include "lod/world_frame.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;

struct Grid {
  explicit Grid(const format::Manifest& m)
      : manifest(m), layout(m.dims(), m.brick), frame(m), boxes(node_world_boxes(layout, frame)) {}
  format::Manifest manifest;
  OctreeLayout layout;
  WorldFrame frame;
  std::vector<WorldBox> boxes;

  LodCut cut(LodOptions options = {}) const { return LodCut(layout, boxes, options); }
  Camera camera(const Vec3& eye, const Vec3& target, double fov = 45) const {
    return look_at(eye, target, fov, 16.0 / 9.0, frame.domain());
  }
  // From the south at 50 degrees elevation, far enough to see the whole domain.
  Camera whole_domain_camera() const {
    const WorldBox& d = frame.domain();
    const double distance = 1.1 * d.radius() / std::sin(22.5 * 3.14159265358979 / 180);
    const double e = 50 * 3.14159265358979 / 180;
    return camera(add(d.center(), Vec3{0, -distance * std::cos(e), distance * std::sin(e)}),
                  d.center());
  }
  // Low and oblique over the domain centre.
  Camera low_camera() const {
    const WorldBox& d = frame.domain();
    const Vec3 ground{0, 0, d.lo[2]};
    return camera(add(ground, Vec3{0, -0.12 * (d.hi[1] - d.lo[1]), 0.2 * (d.hi[2] - d.lo[2])}),
                  ground);
  }
};

const Grid& paper() {
  static const Grid g(testing::paper_manifest());
  return g;
}

const Grid& small() {
  static const Grid g(testing::small_manifest());
  return g;
}

std::set<NodeId> ids(const std::vector<PrioritizedNode>& nodes) {
  std::set<NodeId> out;
  for (const auto& n : nodes) out.insert(n.node);
  return out;
}

// The cut holds no node with an ancestor, and every level-0 node that passes the frustum
// test lies under exactly one cut node.
void expect_valid_cut(const Grid& g, const LodCut& cut, const Camera& camera) {
  const std::set<NodeId> in = ids(cut.nodes());
  ASSERT_EQ(in.size(), cut.nodes().size()) << "a node appears twice";
  const Frustum fr = view_frustum(camera);
  for (NodeId n : in) {
    EXPECT_TRUE(fr.may_intersect(g.boxes[n])) << "culled node " << n << " in the cut";
    for (auto p = g.layout.parent(n); p; p = g.layout.parent(*p)) {
      ASSERT_FALSE(in.count(*p)) << "node " << n << " and its ancestor " << *p;
    }
  }
  const LevelShape& leaves = g.layout.level(0);
  for (NodeId leaf = 0; leaf < leaves.node_count(); ++leaf) {
    if (!fr.may_intersect(g.boxes[leaf])) continue;
    int covering = 0;
    for (std::optional<NodeId> a = leaf; a; a = g.layout.parent(*a)) covering += in.count(*a);
    ASSERT_EQ(covering, 1) << "visible leaf " << leaf;
  }
}

// The cut sorted nearest first (ties by id), as CutDiff lists are.
std::vector<PrioritizedNode> sorted(std::vector<PrioritizedNode> nodes) {
  std::sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) {
    return a.priority < b.priority || (a.priority == b.priority && a.node < b.node);
  });
  return nodes;
}

float centre_distance(const Grid& g, NodeId n, const Camera& c) {
  return static_cast<float>(length(sub(g.boxes[n].center(), c.eye)));
}

TEST(LodCutTest, AFarCameraSeesOnlyTheRoot) {
  const Grid& g = small();
  LodCut cut = g.cut();
  const Camera far = g.camera({0, -1e5, 5e4}, g.frame.domain().center());
  const CutDiff d = cut.update(far);
  ASSERT_EQ(d.added.size(), 1u);
  EXPECT_EQ(d.added[0].node, g.layout.root());
  EXPECT_EQ(d.added[0].priority, centre_distance(g, g.layout.root(), far));
  EXPECT_TRUE(d.removed.empty());
  EXPECT_TRUE(d.reprioritized.empty());
  EXPECT_EQ(cut.nodes(), d.added);
  EXPECT_TRUE(cut.update(far).empty());  // nothing changed
}

TEST(LodCutTest, CutsCoverEveryVisibleLeafExactlyOnce) {
  const Grid& g = small();
  for (double threshold : {0.0, 1e-4, 4e-3, 0.1}) {
    for (const Camera& c : {g.whole_domain_camera(), g.low_camera()}) {
      LodCut cut = g.cut(LodOptions{threshold, 1u << 30, 0.1, 0.25});
      cut.update(c);
      SCOPED_TRACE(::testing::Message() << "threshold " << threshold);
      expect_valid_cut(g, cut, c);
      if (threshold == 0.0) {  // everything visible is split down to level 0
        for (const auto& n : cut.nodes()) EXPECT_LT(n.node, g.layout.level(0).node_count());
      }
    }
  }
}

TEST(LodCutTest, WholeDomainViewOfThePaperGridCoversEveryLeaf) {
  const Grid& g = paper();
  const Camera c = g.whole_domain_camera();
  LodCut cut = g.cut();
  cut.update(c);
  expect_valid_cut(g, cut, c);
  EXPECT_EQ(cut.stats().culled, 0u);  // the whole domain is in view
  EXPECT_FALSE(cut.stats().capped);
  EXPECT_GT(cut.nodes().size(), 20u);
  EXPECT_LT(cut.nodes().size(), 2000u);
}

TEST(LodCutTest, DiffsReplayToTheCutAlongAFlyIn) {
  const Grid& g = paper();
  const WorldCameraPath path(default_fly_in_path(g.frame), g.frame, "fly-in");
  LodCut cut = g.cut();
  const double rel = cut.options().reprioritize_relative;
  std::map<NodeId, float> replica;  // what the server was told
  std::size_t added = 0, removed = 0, reprioritized = 0;
  for (double t = path.start_time() - 1; t <= path.end_time() + 1; t += 0.1) {
    const Camera c = pose_camera(path.sample(t), 16.0 / 9.0, g.frame.domain());
    const CutDiff d = cut.update(c);
    std::set<NodeId> touched;
    for (NodeId n : d.removed) {
      ASSERT_TRUE(replica.erase(n)) << "removed " << n << " was not in the cut";
      ASSERT_TRUE(touched.insert(n).second);
    }
    for (const auto& n : d.added) {
      ASSERT_TRUE(std::isfinite(n.priority));
      ASSERT_EQ(n.priority, centre_distance(g, n.node, c));
      ASSERT_TRUE(replica.emplace(n.node, n.priority).second) << "added " << n.node << " twice";
      ASSERT_TRUE(touched.insert(n.node).second) << n.node << " added and removed";
    }
    for (const auto& n : d.reprioritized) {
      ASSERT_TRUE(replica.count(n.node)) << "reprioritized " << n.node << " not in the cut";
      ASSERT_TRUE(touched.insert(n.node).second) << n.node << " in two lists";
      ASSERT_EQ(n.priority, centre_distance(g, n.node, c));
      replica[n.node] = n.priority;
    }
    ASSERT_TRUE(std::is_sorted(d.removed.begin(), d.removed.end()));
    auto by_priority = [](const auto& a, const auto& b) { return a.priority < b.priority; };
    ASSERT_TRUE(std::is_sorted(d.added.begin(), d.added.end(), by_priority));
    ASSERT_TRUE(std::is_sorted(d.reprioritized.begin(), d.reprioritized.end(), by_priority));
    // The replica holds exactly the cut, with priorities within the re-send tolerance.
    ASSERT_EQ(replica.size(), cut.nodes().size());
    for (const auto& n : cut.nodes()) {
      const auto it = replica.find(n.node);
      ASSERT_NE(it, replica.end()) << n.node;
      ASSERT_TRUE(std::isfinite(n.priority));
      ASSERT_EQ(n.priority, centre_distance(g, n.node, c));
      ASSERT_LE(std::fabs(n.priority - it->second), rel * it->second * (1 + 1e-6) + 1e-6);
    }
    ASSERT_LE(cut.nodes().size(), cut.options().max_nodes);
    added += d.added.size();
    removed += d.removed.size();
    reprioritized += d.reprioritized.size();
  }
  expect_valid_cut(g, cut, pose_camera(path.sample(path.end_time()), 16.0 / 9.0, g.frame.domain()));
  EXPECT_GT(added, 1000u);
  EXPECT_GT(removed, 100u);
  EXPECT_GT(reprioritized, 100u);
}

TEST(LodCutTest, MovingCloserNeverReducesTheNodeCount) {
  const Grid& g = paper();
  const Vec3 centre = g.frame.domain().center();
  for (double hysteresis : {0.0, kDefaultHysteresis}) {
    LodCut cut = g.cut(LodOptions{kDefaultSplitSolidAngleSr, 1u << 30, 0.1, hysteresis});
    std::size_t previous = 0;
    // Straight down on the centre, from far away to where the domain just fills the view.
    for (double h = 20000; h >= 1300; h *= 0.97) {
      const Camera c = g.camera({centre[0], centre[1], h}, {centre[0], centre[1], 0});
      cut.update(c);
      ASSERT_EQ(cut.stats().culled, 0u) << "at " << h << " km the domain leaves the view";
      ASSERT_GE(cut.nodes().size(), previous) << "at " << h << " km";
      previous = cut.nodes().size();
    }
    EXPECT_GT(previous, 50u);
  }
}

TEST(LodCutTest, MaxNodesIsAHardCapServingTheNearestFirst) {
  const Grid& g = paper();
  const Camera c = g.low_camera();
  LodCut free = g.cut(LodOptions{kDefaultSplitSolidAngleSr, 1u << 30, 0.1, 0.25});
  free.update(c);
  for (std::size_t cap : {1u, 8u, 100u, 1000u}) {
    ASSERT_GT(free.nodes().size(), cap);
    LodCut cut = g.cut(LodOptions{kDefaultSplitSolidAngleSr, cap, 0.1, 0.25});
    cut.update(c);
    SCOPED_TRACE(::testing::Message() << "cap " << cap);
    EXPECT_LE(cut.nodes().size(), cap);
    EXPECT_TRUE(cut.stats().capped);
    expect_valid_cut(g, cut, c);
    if (cap >= 100) {
      // Detail goes to the nodes nearest the eye: the nearest quarter of the cut is finer.
      const auto n = sorted(cut.nodes());
      const std::size_t q = n.size() / 4;
      double near_level = 0, far_level = 0;
      for (std::size_t i = 0; i < q; ++i) {
        near_level += g.layout.key(n[i].node).level;
        far_level += g.layout.key(n[n.size() - 1 - i].node).level;
      }
      EXPECT_LT(near_level, far_level);
    }
  }
}

TEST(LodCutTest, NodesOutsideTheViewAreDropped) {
  const Grid& g = paper();
  LodCut cut = g.cut();
  cut.update(g.low_camera());
  const std::size_t before = cut.nodes().size();
  ASSERT_GT(before, 0u);
  EXPECT_GT(cut.stats().culled, 0u);
  // Turn around: look away from the domain.
  const WorldBox& d = g.frame.domain();
  const Camera away = g.camera({0, d.lo[1] - 100, 50}, {0, d.lo[1] - 1000, 50});
  const CutDiff diff = cut.update(away);
  EXPECT_TRUE(cut.nodes().empty());
  EXPECT_TRUE(diff.added.empty());
  EXPECT_EQ(diff.removed.size(), before);
}

TEST(LodCutTest, HysteresisStopsFlickerAtTheThreshold) {
  const Grid& g = paper();
  const Vec3 centre = g.frame.domain().center();
  auto above = [&](double h) {  // straight down, the whole domain in view (nothing culled)
    return g.camera({centre[0], centre[1], h}, {centre[0], centre[1], 0});
  };
  // Two heights 1% apart between which some node crosses the split threshold.
  LodCut probe = g.cut(LodOptions{kDefaultSplitSolidAngleSr, 1u << 30, 0.1, 0.0});
  double high = 20000, low = high;
  probe.update(above(high));
  for (std::size_t count = probe.nodes().size(); low > 1300; high = low) {
    low = high * 0.99;
    probe.update(above(low));
    if (probe.nodes().size() != count) break;
  }
  ASSERT_GT(low, 1300);
  for (double hysteresis : {0.0, kDefaultHysteresis}) {
    LodCut cut = g.cut(LodOptions{kDefaultSplitSolidAngleSr, 1u << 30, 0.1, hysteresis});
    std::size_t churn = 0;
    for (int i = 0; i < 20; ++i) {
      const CutDiff d = cut.update(above(i % 2 ? high : low));
      ASSERT_EQ(cut.stats().culled, 0u);
      if (i >= 2) churn += d.added.size() + d.removed.size();
    }
    if (hysteresis > 0) {
      EXPECT_EQ(churn, 0u);
    } else {
      EXPECT_GT(churn, 0u);  // without it, nodes at the threshold flip every frame
    }
  }
}

TEST(LodCutTest, PrioritiesAreResentOnlyWhenTheyMoveEnough) {
  const Grid& g = paper();
  LodCut cut = g.cut(LodOptions{kDefaultSplitSolidAngleSr, kDefaultMaxNodes, 0.1, 0.99});
  Camera c = g.whole_domain_camera();
  cut.update(c);
  // Creep towards the target by 0.5% per frame: nothing is re-sent at first, and a node
  // is re-sent once its distance moved by more than 10% from what was sent.
  const Vec3 step = scale(sub(c.target, c.eye), 0.005);
  std::map<NodeId, float> sent;
  for (const auto& n : cut.nodes()) sent[n.node] = n.priority;
  bool any = false;
  for (int i = 1; i <= 40; ++i) {
    c.eye = add(c.eye, step);
    const CutDiff d = cut.update(c);
    if (i == 1) {
      EXPECT_TRUE(d.reprioritized.empty());
    }
    for (const auto& n : d.added) sent[n.node] = n.priority;
    for (NodeId n : d.removed) sent.erase(n);
    for (const auto& n : d.reprioritized) {
      EXPECT_GT(std::fabs(n.priority - sent[n.node]), 0.1 * sent[n.node]);
      sent[n.node] = n.priority;
      any = true;
    }
  }
  EXPECT_TRUE(any);
}

TEST(LodCutTest, FullAndResetResendTheWholeCut) {
  const Grid& g = paper();
  LodCut cut = g.cut();
  const Camera c = g.low_camera();
  const CutDiff first = cut.update(c);
  EXPECT_EQ(first.added, sorted(cut.nodes()));
  const CutDiff full = cut.full();
  EXPECT_EQ(full.added, sorted(cut.nodes()));
  EXPECT_TRUE(full.removed.empty());
  EXPECT_TRUE(full.reprioritized.empty());
  cut.reset();
  EXPECT_TRUE(cut.nodes().empty());
  const CutDiff again = cut.update(c);
  EXPECT_EQ(again.added, first.added);
  EXPECT_TRUE(again.removed.empty());
}

TEST(LodCutTest, InvalidCamerasAndOptionsAreRefused) {
  const Grid& g = small();
  LodCut cut = g.cut();
  cut.update(g.low_camera());
  const auto before = cut.nodes();
  Camera bad = g.low_camera();
  bad.fov_y_deg = 0;
  expect_error([&] { cut.update(bad); }, ErrorCode::kInvalidArgument, {"fov"});
  EXPECT_EQ(cut.nodes(), before);

  auto refused = [&](LodOptions o, std::string_view part) {
    expect_error([&] { g.cut(o); }, ErrorCode::kInvalidArgument, {part});
  };
  refused(LodOptions{-1.0, 10, 0.1, 0.25}, "split_solid_angle_sr");
  refused(LodOptions{NAN, 10, 0.1, 0.25}, "split_solid_angle_sr");
  refused(LodOptions{0.01, 0, 0.1, 0.25}, "max_nodes");
  refused(LodOptions{0.01, 10, -0.1, 0.25}, "reprioritize_relative");
  refused(LodOptions{0.01, 10, 0.1, 1.0}, "hysteresis");
  EXPECT_EQ(cut.box(g.layout.root()), g.frame.domain());
  expect_error([&] { cut.box(static_cast<NodeId>(g.layout.node_count())); }, ErrorCode::kNotFound,
               {"does not exist"});
  std::vector<WorldBox> short_boxes(g.boxes.begin(), g.boxes.end() - 1);
  expect_error([&] { LodCut(g.layout, short_boxes); }, ErrorCode::kInvalidArgument,
               {"node boxes"});
}

}  // namespace
}  // namespace strielad::lod
