// SPDX-License-Identifier: Apache-2.0
// What the server tells clients about its files: the dataset's name for its directory,
// paths relative to the root for anything else under it, whole path mentions only.
#include "serve/client_error_text.h"

#include <gtest/gtest.h>

namespace strielad::serve {
namespace {

TEST(ClientErrorTextTest, StoreDirectoryBecomesTheDatasetName) {
  EXPECT_EQ(name_dataset_not_path("dataset 'latest': /srv/stores/runs/7/MANIFEST: bad magic",
                                  "/srv/stores/runs/7", "latest"),
            "dataset 'latest': latest/MANIFEST: bad magic");
  EXPECT_EQ(name_dataset_not_path("/srv/s/a/steps/step-000001.bricks: step 1 node 4: chunk "
                                  "checksum mismatch; /srv/s/a: time step 9 not converted",
                                  "/srv/s/a", "a"),
            "a/steps/step-000001.bricks: step 1 node 4: chunk checksum mismatch; a: time step 9 "
            "not converted");
}

TEST(ClientErrorTextTest, OnlyWholePathMentionsAreReplaced) {
  // /srv/s/a is not a prefix of the store /srv/s/ab.
  EXPECT_EQ(name_dataset_not_path("/srv/s/ab/MANIFEST: x", "/srv/s/a", "a"), "/srv/s/ab/MANIFEST: x");
  EXPECT_EQ(name_dataset_not_path("'/srv/s/a' and /srv/s/a", "/srv/s/a", "d"), "'d' and d");
  EXPECT_EQ(name_dataset_not_path("nothing to hide", "/srv/s/a", "a"), "nothing to hide");
}

TEST(ClientErrorTextTest, PathsUnderTheRootBecomeRelative) {
  EXPECT_EQ(hide_root("/srv/stores/b/steps/x.bricks: short read", "/srv/stores"),
            "b/steps/x.bricks: short read");
  EXPECT_EQ(hide_root("/srv/stores: not a directory", "/srv/stores/"),
            "the server's root: not a directory");
  EXPECT_EQ(hide_root("/srv/stores2/b: other", "/srv/stores"), "/srv/stores2/b: other");
  EXPECT_EQ(hide_root("/x/y: root is /", "/"), "/x/y: root is /");
}

}  // namespace
}  // namespace strielad::serve
