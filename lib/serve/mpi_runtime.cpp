// SPDX-License-Identifier: Apache-2.0
#include "serve/mpi_runtime.h"

#include <mpi.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cstdlib>
#include <string_view>

#include "core/error.h"

namespace strielad::serve {

namespace {

std::optional<int> env_count(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return std::nullopt;
  int value = 0;
  const std::string_view s(text);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size() || value < 1) return std::nullopt;
  return value;
}

bool env_set(const char* name) { return std::getenv(name) != nullptr; }

std::string_view thread_level_name(int level) {
  switch (level) {
    case MPI_THREAD_SINGLE: return "MPI_THREAD_SINGLE";
    case MPI_THREAD_FUNNELED: return "MPI_THREAD_FUNNELED";
    case MPI_THREAD_SERIALIZED: return "MPI_THREAD_SERIALIZED";
    case MPI_THREAD_MULTIPLE: return "MPI_THREAD_MULTIPLE";
    default: return "unknown";
  }
}

}  // namespace

std::optional<int> mpi_launch_size() {
  if (auto n = env_count("OMPI_COMM_WORLD_SIZE")) return n;  // Open MPI's mpirun
  if (auto n = env_count("PMI_SIZE")) return n;              // PMI-1/2 (srun --mpi=pmi2)
  if (env_set("PMIX_RANK")) {                                // PMIx (srun --mpi=pmix)
    if (auto n = env_count("SLURM_STEP_NUM_TASKS")) return n;
    if (auto n = env_count("PMIX_SIZE")) return n;
    return 2;  // let MPI tell the size
  }
  if (env_set("SLURM_PROCID")) {
    if (auto n = env_count("SLURM_STEP_NUM_TASKS"); n && *n > 1) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "srun started {} tasks of strielad-serve without an MPI plugin, so each "
                       "would be a separate server: run it with 'srun --mpi=pmix' (or pmi2) or "
                       "with mpirun inside the allocation, or with one task",
                       *n);
    }
  }
  return std::nullopt;
}

MpiRuntime::MpiRuntime() {
  // Open MPI yields the processor inside every MPI call that finds nothing to do when a
  // node is oversubscribed; the MPI threads here only poll and sleep between polls, so a
  // yield just delays them behind busy processes (several ms each on a loaded node).
  // A value the user set (--mca mpi_yield_when_idle 1) stays.
  ::setenv("OMPI_MCA_mpi_yield_when_idle", "0", 0);
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  char name[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(name, &length);
  host_.assign(name, static_cast<std::size_t>(std::max(length, 0)));
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw make_error(ErrorCode::kUnsupported,
                     "the MPI library gives {} but strielad-serve needs MPI_THREAD_FUNNELED",
                     thread_level_name(provided));
  }
  spdlog::debug("rank {} of {} on {}: MPI initialised ({} provided)", rank_, size_, host_,
                thread_level_name(provided));
}

MpiRuntime::~MpiRuntime() { MPI_Finalize(); }

void MpiRuntime::abort(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::abort();  // MPI_Abort does not return
}

struct MpiChannel::Impl {
  std::vector<MPI_Request> requests;
  std::vector<std::vector<std::byte>> buffers;  // buffers[i] belongs to requests[i]
};

MpiChannel::MpiChannel() : impl_(std::make_unique<Impl>()) {}

MpiChannel::~MpiChannel() {
  if (progress() == 0) return;
  spdlog::warn("MPI: {} messages still being sent at shutdown", impl_->requests.size());
  for (std::size_t i = 0; i < impl_->requests.size(); ++i) {
    MPI_Request_free(&impl_->requests[i]);
    // MPI may still read the buffer: hand it over for good.
    new std::vector<std::byte>(std::move(impl_->buffers[i]));
  }
}

void MpiChannel::send(int destination, int tag, std::vector<std::byte> bytes) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) {
    throw make_error(ErrorCode::kInternal, "MPI message of {} bytes is too large", bytes.size());
  }
  MPI_Request request = MPI_REQUEST_NULL;
  // The vector's heap buffer does not move when the vector itself is moved below.
  MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination, tag,
            MPI_COMM_WORLD, &request);
  impl_->requests.push_back(request);
  impl_->buffers.push_back(std::move(bytes));
}

std::optional<MpiChannel::Message> MpiChannel::receive() {
  progress();
  int flag = 0;
  MPI_Message handle = MPI_MESSAGE_NULL;
  MPI_Status status;
  MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &handle, &status);
  if (!flag) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  Message message;
  message.source = status.MPI_SOURCE;
  message.tag = status.MPI_TAG;
  message.bytes.resize(static_cast<std::size_t>(std::max(count, 0)));
  MPI_Mrecv(message.bytes.data(), count, MPI_BYTE, &handle, MPI_STATUS_IGNORE);
  return message;
}

std::size_t MpiChannel::progress() {
  auto& requests = impl_->requests;
  if (requests.empty()) return 0;
  std::vector<int> done(requests.size());
  int count = 0;
  MPI_Testsome(static_cast<int>(requests.size()), requests.data(), &count, done.data(),
               MPI_STATUSES_IGNORE);
  if (count == MPI_UNDEFINED || count == 0) return requests.size();
  // Completed requests are MPI_REQUEST_NULL now: drop them with their buffers.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (requests[i] == MPI_REQUEST_NULL) continue;
    if (kept != i) {  // a vector moved onto itself would free the buffer MPI still reads
      requests[kept] = requests[i];
      impl_->buffers[kept] = std::move(impl_->buffers[i]);
    }
    ++kept;
  }
  requests.resize(kept);
  impl_->buffers.resize(kept);
  return kept;
}

std::size_t MpiChannel::pending_sends() const { return impl_->requests.size(); }

}  // namespace strielad::serve
