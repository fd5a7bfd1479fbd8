// `blaze run` with the rolling laws in double (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_rolling<double>(const blaze::Scene&, const blaze::app::Options&);
