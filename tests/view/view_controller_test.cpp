// SPDX-License-Identifier: Apache-2.0
// view::ViewController against a real in-process server on the sphere store: the
// complete cut shows meshes exactly where the sphere is, a time step change keeps the
// old meshes (stale) until the new ones replace them, results of a superseded request
// are never shown, a change of vertical exaggeration keeps the meshes of nodes that
// stay in the cut, and invalid input is refused without disturbing the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include "core/error.h"
#include "lod/camera.h"
#include "scene/scene.h"
#include "support/expect_error.h"
#include "support/sphere_store.h"
#include "support/temp_dir.h"
#include "view/local_server.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad::testing {
namespace {

using namespace std::chrono_literals;

// Seen from the south, level with the sphere centres (world km, exaggeration 10).
const Vec3 kEye{5.0, -320.0, 55.0};
const Vec3 kTarget{5.0, 0.0, 55.0};
// Close enough that the frustum leaves out some nodes, and different ones at different
// exaggerations.
const Vec3 kCloseEye{5.0, -100.0, 55.0};

SubVolume sphere(double radius) {
  SubVolume s;
  s.id = 1;
  s.name = "d1";
  s.limits.push_back(Limit{.var = "d1", .min = std::nullopt, .max = radius});
  return s;
}

Scene sphere_scene(double radius) {
  Scene scene;
  scene.subvolumes = {sphere(radius)};
  return scene;
}

// A server on the store, a link to it and a controller on the link, destroyed in the
// reverse order (controller, link, client, server).
struct Session {
  view::LocalConnection connection;
  std::unique_ptr<view::ViewLink> link;
  std::unique_ptr<view::ViewController> controller;

  Session(const std::filesystem::path& store, const Scene& scene) {
    connection = view::open_local_store(store, view::LocalServerOptions{.threads = 2});
    link = std::make_unique<view::ViewLink>(std::move(connection.client));
    controller = std::make_unique<view::ViewController>(*link, scene);
  }
};

lod::Camera camera_of(const view::ViewController& controller, const Vec3& eye = kEye,
                      const Vec3& target = kTarget) {
  return lod::look_at(eye, target, 45.0, 1.0, controller.frame().domain());
}

// Updates until the request is answered for every node of a cut that no longer changes;
// adds the results of older requests it dropped to `superseded`.
::testing::AssertionResult update_until_complete(view::ViewController& controller,
                                                 const lod::Camera& camera,
                                                 std::size_t* superseded = nullptr) {
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (true) {
    const auto counters = controller.update(camera);
    if (superseded != nullptr) *superseded += counters.superseded;
    if (controller.connection_lost()) {
      return ::testing::AssertionFailure()
             << "connection lost: " << controller.last_error().value_or("?");
    }
    if (counters.cut_changes == 0 && controller.complete()) {
      return ::testing::AssertionSuccess();
    }
    if (std::chrono::steady_clock::now() > deadline) {
      return ::testing::AssertionFailure()
             << "not complete after 60 s: " << controller.meshes().pending() << " of "
             << controller.meshes().size() << " nodes pending";
    }
    std::this_thread::sleep_for(1ms);
  }
}

double distance_to_box(const Vec3& p, const lod::WorldBox& box) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({box.lo[a] - p[a], 0.0, p[a] - box.hi[a]});
    d2 += d * d;
  }
  return std::sqrt(d2);
}

std::set<NodeId> nodes_with_mesh(const view::ViewController& controller) {
  std::set<NodeId> out;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    if (entry.mesh != nullptr) out.insert(node);
  }
  return out;
}

std::map<NodeId, std::size_t> triangles_per_node(const view::ViewController& controller) {
  std::map<NodeId, std::size_t> out;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    if (entry.mesh != nullptr) out[node] = entry.mesh->triangle_count();
  }
  return out;
}

std::size_t total_triangles(const std::map<NodeId, std::size_t>& per_node) {
  std::size_t n = 0;
  for (const auto& [node, triangles] : per_node) n += triangles;
  return n;
}

std::set<NodeId> cut_nodes(const view::ViewController& controller) {
  std::set<NodeId> out;
  for (const auto& n : controller.cut().nodes()) out.insert(n.node);
  return out;
}

// Every node of the cut has a current entry, and no entry is outside the cut.
void expect_every_cut_node_current(const view::ViewController& controller) {
  const auto& entries = controller.meshes().entries();
  EXPECT_EQ(entries.size(), controller.cut().nodes().size());
  for (const auto& n : controller.cut().nodes()) {
    const auto it = entries.find(n.node);
    ASSERT_NE(it, entries.end()) << "node " << n.node << " of the cut has no entry";
    EXPECT_TRUE(it->second.current) << "node " << n.node;
  }
}

// The nodes of the cut whose box the ball of `radius` about `centre` reaches.
std::set<NodeId> nodes_touched(const view::ViewController& controller, const Vec3& centre,
                               double radius) {
  std::set<NodeId> out;
  for (const auto& n : controller.cut().nodes()) {
    if (distance_to_box(centre, controller.cut().box(n.node)) < radius) out.insert(n.node);
  }
  return out;
}

class ViewControllerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    store_ = new std::filesystem::path(write_sphere_store(dir_->path()));
  }
  static void TearDownTestSuite() {
    delete store_;
    delete dir_;
    store_ = nullptr;
    dir_ = nullptr;
  }

  static inline TempDir* dir_ = nullptr;
  static inline std::filesystem::path* store_ = nullptr;
};

TEST_F(ViewControllerTest, ACompleteCutShowsMeshesExactlyWhereTheSphereIs) {
  Session session(*store_, sphere_scene(30.0));
  auto& controller = *session.controller;
  const auto camera = camera_of(controller);
  ASSERT_TRUE(update_until_complete(controller, camera));
  ASSERT_GT(controller.cut().nodes().size(), 1u);
  expect_every_cut_node_current(controller);
  const auto touched = nodes_touched(controller, kSphereCenter1, 30.0);
  ASSERT_FALSE(touched.empty());
  EXPECT_EQ(nodes_with_mesh(controller), touched);
  EXPECT_LT(touched.size(), controller.cut().nodes().size());  // some nodes are empty
  EXPECT_FALSE(controller.last_error().has_value()) << *controller.last_error();
  EXPECT_EQ(controller.failed_nodes(), 0u);
}

TEST_F(ViewControllerTest, ATimeStepChangeShowsTheOldMeshesStaleUntilReplaced) {
  Session session(*store_, sphere_scene(30.0));
  auto& controller = *session.controller;
  const auto camera = camera_of(controller);
  ASSERT_TRUE(update_until_complete(controller, camera));
  std::map<NodeId, std::shared_ptr<const view::NodeGeometry>> before;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    if (entry.mesh) before[node] = entry.mesh;
  }
  ASSERT_FALSE(before.empty());

  controller.set_time(1);
  EXPECT_EQ(controller.time_step(), 1u);
  EXPECT_FALSE(controller.complete());
  EXPECT_EQ(controller.meshes().stale_shown(), before.size());
  for (const auto& [node, entry] : controller.meshes().entries()) {
    EXPECT_FALSE(entry.current) << "node " << node;
    const auto it = before.find(node);
    if (it == before.end()) {
      EXPECT_EQ(entry.mesh, nullptr) << "node " << node;
    } else {
      EXPECT_EQ(entry.mesh, it->second) << "node " << node << " lost its mesh";
    }
  }

  ASSERT_TRUE(update_until_complete(controller, camera));
  expect_every_cut_node_current(controller);
  EXPECT_EQ(controller.meshes().stale_shown(), 0u);
  std::size_t changed = 0;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    const auto it = before.find(node);
    if (it == before.end() ? entry.mesh != nullptr : entry.mesh != it->second) ++changed;
  }
  EXPECT_GT(changed, 0u);
  // In step 1 the sphere is 10 km further east.
  const Vec3 moved{kSphereCenter1[0] + kSphereStepShiftKm, kSphereCenter1[1],
                        kSphereCenter1[2]};
  EXPECT_EQ(nodes_with_mesh(controller), nodes_touched(controller, moved, 30.0));
}

// The triangles per node of radius 30 seen by a controller that never asked for
// anything else.
std::map<NodeId, std::size_t> fresh_radius_30(const std::filesystem::path& store) {
  Session fresh(store, sphere_scene(30.0));
  EXPECT_TRUE(update_until_complete(*fresh.controller, camera_of(*fresh.controller)));
  return triangles_per_node(*fresh.controller);
}

TEST_F(ViewControllerTest, ResultsOfASupersededSceneAreNeverShown) {
  const auto expected = fresh_radius_30(*store_);
  ASSERT_FALSE(expected.empty());

  Session session(*store_, sphere_scene(25.0));
  auto& controller = *session.controller;
  const auto camera = camera_of(controller);
  ASSERT_TRUE(update_until_complete(controller, camera));
  ASSERT_NE(total_triangles(triangles_per_node(controller)), total_triangles(expected))
      << "radius 25 and 30 must differ for this test to mean anything";

  // Radius 20, and before the render thread takes any of its results, radius 30: the
  // results of radius 20 the link receives meanwhile must all be dropped.
  const auto results_before = session.link->counters().results;
  controller.set_scene(sphere_scene(20.0));
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (session.link->counters().results == results_before &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(1ms);
  }
  ASSERT_GT(session.link->counters().results, results_before) << "no result for radius 20";
  controller.set_scene(sphere_scene(30.0));
  std::size_t superseded = 0;
  ASSERT_TRUE(update_until_complete(controller, camera, &superseded));
  EXPECT_GT(superseded, 0u);
  expect_every_cut_node_current(controller);
  const auto shown = triangles_per_node(controller);
  EXPECT_EQ(total_triangles(shown), total_triangles(expected));
  EXPECT_EQ(shown, expected);
}

TEST_F(ViewControllerTest, BackToBackSceneChangesShowOnlyTheLastScene) {
  const auto expected = fresh_radius_30(*store_);
  ASSERT_FALSE(expected.empty());

  Session session(*store_, sphere_scene(25.0));
  auto& controller = *session.controller;
  const auto camera = camera_of(controller);
  ASSERT_TRUE(update_until_complete(controller, camera));
  controller.set_scene(sphere_scene(20.0));
  controller.update(camera);
  controller.set_scene(sphere_scene(30.0));
  ASSERT_TRUE(update_until_complete(controller, camera));
  expect_every_cut_node_current(controller);
  const auto shown = triangles_per_node(controller);
  EXPECT_EQ(total_triangles(shown), total_triangles(expected));
  EXPECT_EQ(shown, expected);
}

TEST_F(ViewControllerTest, AnExaggerationChangeKeepsTheMeshesOfNodesThatStay) {
  Session session(*store_, sphere_scene(30.0));
  auto& controller = *session.controller;
  ASSERT_TRUE(update_until_complete(controller, camera_of(controller, kCloseEye)));
  const auto cut_before = cut_nodes(controller);
  std::map<NodeId, std::shared_ptr<const view::NodeGeometry>> before;
  for (const auto& [node, entry] : controller.meshes().entries()) before[node] = entry.mesh;

  controller.set_vertical_exaggeration(5.0);
  EXPECT_EQ(controller.options().vertical_exaggeration, 5.0);
  const auto camera = camera_of(controller, kCloseEye);
  const auto counters = controller.update(camera);
  EXPECT_GT(counters.cut_changes, 0u);
  const auto cut_after = cut_nodes(controller);
  EXPECT_NE(cut_after, cut_before);
  std::size_t stayed = 0, stayed_with_mesh = 0;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    const auto it = before.find(node);
    if (it == before.end()) continue;
    ++stayed;
    if (it->second) ++stayed_with_mesh;
    EXPECT_EQ(entry.mesh, it->second) << "node " << node;
    EXPECT_TRUE(entry.current) << "node " << node;
  }
  EXPECT_GT(stayed, 0u);
  EXPECT_GT(stayed_with_mesh, 0u);
  // Nodes that left the cut are gone from the meshes.
  for (const NodeId node : cut_before) {
    if (!cut_after.contains(node)) {
      EXPECT_FALSE(controller.meshes().entries().contains(node)) << "node " << node;
    }
  }
  ASSERT_TRUE(update_until_complete(controller, camera));
  expect_every_cut_node_current(controller);
}

TEST_F(ViewControllerTest, InvalidInputIsRefusedAndTheViewKeepsWorking) {
  Session session(*store_, sphere_scene(30.0));
  auto& controller = *session.controller;
  const auto camera = camera_of(controller);
  ASSERT_TRUE(update_until_complete(controller, camera));
  const Scene scene = controller.scene();
  const auto epoch = controller.epoch();
  const auto meshes = triangles_per_node(controller);

  Scene unknown = sphere_scene(30.0);
  unknown.subvolumes[0].limits[0].var = "no_such_var";
  expect_error([&] { controller.set_scene(unknown); }, ErrorCode::kNotFound, {"no_such_var"});
  expect_error([&] { controller.set_time(99); }, ErrorCode::kNotFound, {"99"});
  expect_error([&] { controller.set_vertical_exaggeration(0.0); }, ErrorCode::kInvalidArgument,
               {"exaggeration"});
  expect_error([&] { controller.set_vertical_exaggeration(std::nan("")); },
               ErrorCode::kInvalidArgument, {"exaggeration"});
  expect_error([&] { controller.set_vertical_exaggeration(-1.0); },
               ErrorCode::kInvalidArgument, {"exaggeration"});

  // Nothing changed: same scene, step, exaggeration, request, cut and meshes.
  EXPECT_EQ(controller.scene(), scene);
  EXPECT_EQ(controller.time_step(), 0u);
  EXPECT_EQ(controller.options().vertical_exaggeration, lod::kDefaultVerticalExaggeration);
  EXPECT_EQ(controller.epoch(), epoch);
  EXPECT_TRUE(controller.complete());
  EXPECT_EQ(controller.update(camera).cut_changes, 0u);
  EXPECT_TRUE(controller.complete());
  EXPECT_EQ(triangles_per_node(controller), meshes);

  // And it still answers valid requests.
  controller.set_time(1);
  ASSERT_TRUE(update_until_complete(controller, camera));
  expect_every_cut_node_current(controller);
  EXPECT_FALSE(controller.last_error().has_value()) << *controller.last_error();
  const Vec3 moved{kSphereCenter1[0] + kSphereStepShiftKm, kSphereCenter1[1],
                        kSphereCenter1[2]};
  EXPECT_EQ(nodes_with_mesh(controller), nodes_touched(controller, moved, 30.0));
}

}  // namespace
}  // namespace strielad::testing
