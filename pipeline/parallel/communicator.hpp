// The ranks of a run and what they say to each other (issue 21), over MPI (Debian's Open MPI; one
// rank per GPU) when the build has it (BLAZE_MPI=1: the Makefile's mpi programs), else one rank
// that talks to itself: the same code runs without MPI, at no cost.
//   exchange(out)  out[r] to rank r, from every rank at once; returns what each rank sent here
//                  (MPI_Alltoall of the sizes, MPI_Alltoallv of the bytes; messages over 2 GiB
//                  are refused, as MPI's int counts cannot hold them);
//   sum, max, all_gather, broadcast: collectives on plain values.
// Every rank must make the same calls in the same order (they are collective).
#pragma once
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <vector>
#if BLAZE_MPI
#include <mpi.h>
#endif

namespace blaze {

struct CommunicatorError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Communicator {
 public:
  // Every rank of the run (MPI_COMM_WORLD).
  Communicator() {
#if BLAZE_MPI
    int on = 0;
    MPI_Initialized(&on);
    if (!on) throw CommunicatorError("communicator: MPI is not initialised (MpiSession in main)");
    comm_ = std::make_shared<MPI_Comm>(MPI_COMM_WORLD);
    MPI_Comm_rank(*comm_, &rank_);
    MPI_Comm_size(*comm_, &size_);
#endif
  }
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Collective: the first n ranks as a run of their own (a restart onto fewer ranks, tests); on the
  // others a communicator of no ranks (size 0), which must not be used.
  Communicator first(int n) const {
    if (n < 1 || n > size_) throw CommunicatorError("communicator: the first " + std::to_string(n) + " of " + std::to_string(size_) + " ranks");
    Communicator c = *this;
#if BLAZE_MPI
    MPI_Comm sub = MPI_COMM_NULL;
    check(MPI_Comm_split(*comm_, rank_ < n ? 0 : MPI_UNDEFINED, rank_, &sub), "MPI_Comm_split");
    if (sub == MPI_COMM_NULL) {
      c.comm_.reset(), c.rank_ = -1, c.size_ = 0;
      return c;
    }
    c.comm_ = std::shared_ptr<MPI_Comm>(new MPI_Comm(sub), [](MPI_Comm* m) {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (!finalized) MPI_Comm_free(m);
      delete m;
    });
    MPI_Comm_rank(sub, &c.rank_);
    MPI_Comm_size(sub, &c.size_);
#endif
    return c;
  }

  std::vector<std::string> exchange(const std::vector<std::string>& out) const {
    if (out.size() != static_cast<std::size_t>(size_))
      throw CommunicatorError("communicator: " + std::to_string(out.size()) + " messages for " + std::to_string(size_) + " ranks");
#if BLAZE_MPI
    std::vector<int> send_n(static_cast<std::size_t>(size_)), recv_n(static_cast<std::size_t>(size_));
    std::vector<int> send_at(static_cast<std::size_t>(size_)), recv_at(static_cast<std::size_t>(size_));
    std::string send;
    for (int r = 0; r < size_; ++r) {
      const std::string& m = out[static_cast<std::size_t>(r)];
      if (m.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
          send.size() + m.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw CommunicatorError("communicator: rank " + std::to_string(rank_) + " would send more than 2 GiB at once");
      send_at[static_cast<std::size_t>(r)] = static_cast<int>(send.size());
      send_n[static_cast<std::size_t>(r)] = static_cast<int>(m.size());
      send += m;
    }
    check(MPI_Alltoall(send_n.data(), 1, MPI_INT, recv_n.data(), 1, MPI_INT, *comm_), "MPI_Alltoall");
    long total = 0;
    for (int r = 0; r < size_; ++r) {
      recv_at[static_cast<std::size_t>(r)] = static_cast<int>(total);
      total += recv_n[static_cast<std::size_t>(r)];
      if (total > std::numeric_limits<int>::max())
        throw CommunicatorError("communicator: rank " + std::to_string(rank_) + " would receive more than 2 GiB at once");
    }
    std::string recv(static_cast<std::size_t>(total), '\0');
    check(MPI_Alltoallv(send.data(), send_n.data(), send_at.data(), MPI_BYTE, recv.data(), recv_n.data(), recv_at.data(), MPI_BYTE,
                        *comm_),
          "MPI_Alltoallv");
    std::vector<std::string> in(static_cast<std::size_t>(size_));
    for (int r = 0; r < size_; ++r)
      in[static_cast<std::size_t>(r)] = recv.substr(static_cast<std::size_t>(recv_at[static_cast<std::size_t>(r)]),
                                                    static_cast<std::size_t>(recv_n[static_cast<std::size_t>(r)]));
    return in;
#else
    return out;
#endif
  }

  double sum(double v) const { return reduce(v, kSum); }
  long sum(long v) const { return reduce(v, kSum); }
  double max(double v) const { return reduce(v, kMax); }
  long max(long v) const { return reduce(v, kMax); }
  double min(double v) const { return reduce(v, kMin); }
  // Every rank's v, in rank order (a plain value).
  template <class T>
  std::vector<T> all_gather(const T& v) const {
    std::vector<T> all(static_cast<std::size_t>(size_));
#if BLAZE_MPI
    check(MPI_Allgather(&v, sizeof(T), MPI_BYTE, all.data(), sizeof(T), MPI_BYTE, *comm_), "MPI_Allgather");
#else
    all[0] = v;
#endif
    return all;
  }
  // Every rank's bytes, in rank order.
  std::vector<std::string> all_gather_bytes(const std::string& mine) const {
    std::vector<std::string> out(static_cast<std::size_t>(size_), mine);
    return exchange(out);
  }
  // Every rank's `mine` on rank `root`, in rank order (empty strings on the others): what a gather
  // to one rank moves, 1/size of all_gather_bytes' (an exchange sending to `root` only).
  std::vector<std::string> gather_bytes(const std::string& mine, int root) const {
    if (root < 0 || root >= size_) throw CommunicatorError("communicator: gather to rank " + std::to_string(root) + " of " + std::to_string(size_));
    std::vector<std::string> out(static_cast<std::size_t>(size_));
    out[static_cast<std::size_t>(root)] = mine;
    return exchange(out);
  }
  void barrier() const {
#if BLAZE_MPI
    check(MPI_Barrier(*comm_), "MPI_Barrier");
#endif
  }

 private:
  enum Op { kSum, kMax, kMin };
  template <class T>
  T reduce(T v, Op op) const {
#if BLAZE_MPI
    T out{};
    const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : MPI_LONG;
    check(MPI_Allreduce(&v, &out, 1, type, op == kSum ? MPI_SUM : op == kMax ? MPI_MAX : MPI_MIN, *comm_), "MPI_Allreduce");
    return out;
#else
    (void)op;
    return v;
#endif
  }
#if BLAZE_MPI
  static void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw CommunicatorError(std::string("communicator: ") + what + " failed (MPI error " + std::to_string(code) + ")");
  }
#endif
  int rank_ = 0, size_ = 1;
#if BLAZE_MPI
  std::shared_ptr<MPI_Comm> comm_;  // shared by copies; a split one freed with its last copy
#endif
};

#if BLAZE_MPI
// MPI for the life of main(): initialised first, finalised last.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv) { MPI_Init(argc, argv); }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};
#endif

// A study program's ranks (study_mill, study_hopper): in an MPI build MPI is started (finalised
// when the program ends), ranks other than 0 print nothing on stdout (one voice; errors still reach
// stderr) and rank 0 says how many run; in a build without MPI none (one process, no Communicator).
inline const Communicator* study_ranks([[maybe_unused]] int* argc, [[maybe_unused]] char*** argv, [[maybe_unused]] const char* program) {
#if BLAZE_MPI
  static MpiSession mpi(argc, argv);
  static const Communicator world;
  if (world.rank() != 0 && !std::freopen("/dev/null", "w", stdout)) throw CommunicatorError("cannot silence rank " + std::to_string(world.rank()));
  if (world.size() > 1) std::printf("%s: over %d ranks (MPI)\n", program, world.size());
  return &world;
#else
  return nullptr;
#endif
}

// For a program's error report: "rank K: " when it runs over several ranks, else "".
inline std::string rank_label() {
#if BLAZE_MPI
  int on = 0, size = 1, rank = 0;
  MPI_Initialized(&on);
  if (on) MPI_Comm_size(MPI_COMM_WORLD, &size), MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (size > 1) return "rank " + std::to_string(rank) + ": ";
#endif
  return "";
}
// A program's exit on an error: over several ranks every rank stops (MPI_Abort; the others may be
// waiting in a collective), else `code` is returned.
inline int stop_ranks(int code) {
#if BLAZE_MPI
  int on = 0, size = 1;
  MPI_Initialized(&on);
  if (on) MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) {
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, code);
  }
#endif
  return code;
}

}  // namespace blaze
