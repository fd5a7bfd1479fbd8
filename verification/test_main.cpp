// Boost.Test entry point of the verification suite (one binary per backend).
#define BOOST_TEST_MODULE blaze_verification
#if defined(BLAZE_TEST_HEADER_ONLY)
#include <boost/test/included/unit_test.hpp>  // GPU machine: Boost headers only
#else
#include <boost/test/unit_test.hpp>
#endif
#include "blaze/exec/device_info.hpp"

struct ReportBackend {
  ReportBackend() {
    BOOST_TEST_MESSAGE("blaze verification on " << blaze::DefaultSpace::name << ": "
                                                << blaze::device_name(blaze::DefaultSpace{}));
  }
};
BOOST_TEST_GLOBAL_FIXTURE(ReportBackend);
