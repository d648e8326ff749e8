// SPDX-License-Identifier: Apache-2.0
// MPI for strielad-serve: whether a launcher started this process as one of several
// ranks, MPI's lifetime, and byte messages between ranks. One thread per rank makes
// every MPI call (the thread that constructed the MpiRuntime), so MPI_THREAD_FUNNELED is
// all that is asked for; other threads talk to it through queues. mpi.h stays in the
// .cpp files.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace strielad::serve {

// The number of ranks an MPI launcher started, read from its environment without any
// MPI call: OMPI_COMM_WORLD_SIZE (Open MPI's mpirun), PMI_SIZE (srun --mpi=pmi2, MPICH),
// or SLURM_STEP_NUM_TASKS when PMIX_RANK is set (srun --mpi=pmix). Nothing when the
// process was not started by an MPI launcher.
// \error kInvalidArgument when srun started several tasks without an MPI plugin (each
// would be a lone server fighting for the port): use mpirun or srun --mpi=pmix.
std::optional<int> mpi_launch_size();

class MpiRuntime {
 public:
  // MPI_Init_thread asking for MPI_THREAD_FUNNELED; the calling thread is the one that
  // may make MPI calls from then on, and must destroy the runtime (MPI_Finalize).
  // \error kUnsupported when the MPI library offers less than MPI_THREAD_FUNNELED.
  MpiRuntime();
  ~MpiRuntime();
  MpiRuntime(const MpiRuntime&) = delete;
  MpiRuntime& operator=(const MpiRuntime&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  const std::string& host() const { return host_; }  // MPI_Get_processor_name
  // Ends every rank of the job at once (MPI_Abort), for a broken invariant.
  [[noreturn]] static void abort(int status);

 private:
  int rank_ = 0;
  int size_ = 1;
  std::string host_;
};

// Byte messages on MPI_COMM_WORLD. Sends never block (MPI_Isend; the buffer is kept until
// the send completes), receives are polled (MPI_Improbe + MPI_Mrecv), so two ranks
// sending large messages to each other cannot deadlock. Only the MPI thread may use it.
class MpiChannel {
 public:
  struct Message {
    int source = 0;
    int tag = 0;
    std::vector<std::byte> bytes;
  };

  MpiChannel();
  ~MpiChannel();  // frees sends still pending (their buffers stay until MPI completes them)

  void send(int destination, int tag, std::vector<std::byte> bytes);
  // The next message that has arrived, if any; also completes finished sends.
  std::optional<Message> receive();
  // Completes finished sends; returns how many are still pending.
  std::size_t progress();
  std::size_t pending_sends() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Sleep lengths for a polling loop (MPI cannot wake a thread that waits on a condition
// variable): 10 us right after activity, doubling up to 250 us while there was activity
// in the last 50 ms, up to 2 ms after that, so a busy rank answers within a fraction of
// a millisecond and an idle one wakes 500 times a second.
class PollBackoff {
 public:
  void reset() {
    next_ = kMin;
    last_active_ = std::chrono::steady_clock::now();
  }
  std::chrono::microseconds next() {
    const auto cap = std::chrono::steady_clock::now() - last_active_ < kRecent ? kBusyMax : kIdleMax;
    const auto now = std::min(next_, cap);
    next_ = std::min(next_ * 2, kIdleMax);
    return now;
  }

 private:
  static constexpr std::chrono::microseconds kMin{10};
  static constexpr std::chrono::microseconds kBusyMax{250};
  static constexpr std::chrono::microseconds kIdleMax{2000};
  static constexpr std::chrono::milliseconds kRecent{50};
  std::chrono::microseconds next_ = kMin;
  std::chrono::steady_clock::time_point last_active_ = std::chrono::steady_clock::now();
};

}  // namespace strielad::serve
