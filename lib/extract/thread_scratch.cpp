// SPDX-License-Identifier: Apache-2.0
#include "extract/thread_scratch.h"

namespace strielad {

ExtractScratch& this_thread_scratch() {
  thread_local ExtractScratch scratch;
  return scratch;
}

}  // namespace strielad
