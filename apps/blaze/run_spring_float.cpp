// `blaze run` with the spring laws in float (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_spring<float>(const blaze::Scene&, const blaze::app::Options&);
