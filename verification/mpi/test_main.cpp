// Boost.Test entry point of the MPI suite (issue 21): `make test` runs it on 1-4 ranks
// (mpirun -np N, oversubscribed on CI's two cores). MPI lives for the whole of main; only rank 0
// writes the table's rows (BLAZE_REPORT). Checks are collective: every rank takes the same path
// (no BOOST_TEST_REQUIRE, which would leave the other ranks waiting in a collective).
#define BOOST_TEST_MODULE blaze_mpi_verification
#define BOOST_TEST_NO_MAIN
#define BOOST_TEST_ALTERNATIVE_INIT_API
#if defined(BLAZE_TEST_HEADER_ONLY)
#include <boost/test/included/unit_test.hpp>  // GPU machine: Boost headers only
#else
#include <boost/test/unit_test.hpp>
#endif
#include <cstdlib>
#include "pipeline/parallel/communicator.hpp"

int main(int argc, char* argv[]) {
  blaze::MpiSession mpi(&argc, &argv);
  const blaze::Communicator comm;
  if (comm.rank() != 0) setenv("BLAZE_REPORT", "", 1);
  return boost::unit_test::unit_test_main(init_unit_test, argc, argv);
}
