// What apps/blaze/run_*.cpp instantiate (run_scene.hpp), as main.cpp sees it.
#pragma once
#include <string>
#include <vector>
#include "blaze/scene/scene.hpp"

namespace blaze {
class Communicator;  // pipeline/parallel/communicator.hpp
}

namespace blaze::app {

struct Options {
  std::string scene, restart;
  std::vector<std::string> overrides;
  bool quiet = false, check = false, phases = false;
  const Communicator* comm = nullptr;  // the ranks of an MPI build under mpirun (null: one process)
};


template <class Real>
int run_history_free(const Scene& s, const Options& o);
template <class Real>
int run_spring(const Scene& s, const Options& o);
template <class Real>
int run_rolling(const Scene& s, const Options& o);

}  // namespace blaze::app
