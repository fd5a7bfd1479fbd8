// `blaze run` with the rolling laws in float (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_rolling<float>(const blaze::Scene&, const blaze::app::Options&);
