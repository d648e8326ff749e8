// SPDX-License-Identifier: Apache-2.0
// Slices through an in-process server (formats/protocol.md version 2): a version-2
// client gets one slice result per scene slice in every NodeResult, with the same meshes
// as extraction in-process; the server counts slice meshes and triangles; a version-1
// client keeps working and is refused a scene with slices with a clear message.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "client/server_client.h"
#include "extract/node_extraction.h"
#include "serve/server.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/server_results.h"
#include "support/sphere_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

class SliceServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    store_path_ = new std::filesystem::path(testing::write_sphere_store(dir_->path()));
  }
  static void TearDownTestSuite() {
    delete store_path_;
    delete dir_;
  }
  void SetUp() override {
    serve::ServerConfig config;
    config.root = store_path_->parent_path();
    config.listen = net::Endpoint{"127.0.0.1", 0};
    config.threads = 2;
    config.cache_bytes = 64 << 20;
    server_ = std::make_unique<serve::Server>(config);
    server_->start();
  }
  std::unique_ptr<client::ServerClient> connect(std::uint16_t version) {
    client::ClientOptions o;
    o.protocol_version = version;
    auto c = client::ServerClient::connect(net::Endpoint{"127.0.0.1", server_->port()}, o);
    c->open_dataset(store_path_->filename().string());
    return c;
  }
  static Scene scene() {
    Scene s;
    s.subvolumes = {SubVolume{.id = 1, .name = "", .limits = {Limit{"d1", std::nullopt, 20.0}}, .domain = {}}};
    s.slices = {Slice{.id = 7, .axis = "height", .value = 5500.0, .var = "d2", .colormap = "turbo"},
                Slice{.id = 8, .level_var = "d1", .value = 30.0, .var = "d2"}};
    return s;
  }
  static inline testing::TempDir* dir_ = nullptr;
  static inline std::filesystem::path* store_path_ = nullptr;
  std::unique_ptr<serve::Server> server_;
};

TEST_F(SliceServerTest, Version2ClientReceivesSlicesAsExtractedInProcess) {
  auto c = connect(protocol::kProtocolVersion);
  EXPECT_EQ(c->protocol_version(), 2);
  const auto started = c->set_scene(scene());
  const auto nodes = testing::whole_octree(c->octree());
  c->update_cut(nodes, {}, {});
  const auto results = testing::collect_results(*c, nodes.size(), started.generation);
  const auto store = Store::open(*store_path_);
  const ResolvedScene resolved = resolve_scene(scene(), store->manifest(), "test");
  std::uint64_t meshes = 0, triangles = 0;
  for (const auto& [node, r] : results) {
    ASSERT_EQ(r.slices.size(), 2u);
    const NodeExtraction local = extract_node(*store, nullptr, resolved, 0, node);
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& wire = r.slices[i];
      EXPECT_EQ(wire.slice_id, i == 0 ? 7u : 8u);
      EXPECT_EQ(wire.outcome, local.slices[i].outcome) << node;
      if (wire.outcome != NodeOutcome::kMesh) continue;
      ++meshes;
      triangles += wire.mesh.triangle_count();
      EXPECT_EQ(wire.mesh.attribute_names, (std::vector<std::string>{"d2"}));
      ASSERT_EQ(wire.mesh.triangles, local.slices[i].mesh.triangles);
      // Within the wire's quantization bound: half a step of the mesh's box per axis.
      std::array<double, 3> lo{}, hi{};
      lo = hi = local.slices[i].mesh.positions[0];
      for (const auto& p : local.slices[i].mesh.positions) {
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], p[a]);
          hi[a] = std::max(hi[a], p[a]);
        }
      }
      for (std::size_t v = 0; v < wire.mesh.vertex_count(); ++v) {
        for (int a = 0; a < 3; ++a) {
          EXPECT_NEAR(wire.mesh.positions[v][a], local.slices[i].mesh.positions[v][a],
                      (hi[a] - lo[a]) / 131070.0 * 1.001 + 1e-9);
        }
      }
      if (i == 0) {
        for (const auto& p : wire.mesh.positions) EXPECT_EQ(p[2], 5500.0);  // box ends exact
      }
    }
  }
  EXPECT_GT(meshes, 0u);
  const auto stats = nlohmann::json::parse(c->stats());
  EXPECT_EQ(stats.at("slice_meshes").get<std::uint64_t>(), meshes);
  EXPECT_EQ(stats.at("slice_triangles").get<std::uint64_t>(), triangles);
}

TEST_F(SliceServerTest, Version1ClientKeepsWorkingAndIsRefusedSlices) {
  auto c = connect(1);
  EXPECT_EQ(c->protocol_version(), 1);
  testing::expect_error([&] { c->set_scene(scene()); }, ErrorCode::kUnsupported,
                        {"2 slices", "protocol version 2", "speaks version 1"});
  Scene plain = scene();
  plain.slices.clear();
  const auto started = c->set_scene(plain);
  const auto nodes = testing::whole_octree(c->octree());
  c->update_cut(nodes, {}, {});
  const auto results = testing::collect_results(*c, nodes.size(), started.generation);
  for (const auto& [node, r] : results) EXPECT_TRUE(r.slices.empty());
}

}  // namespace
}  // namespace strielad
