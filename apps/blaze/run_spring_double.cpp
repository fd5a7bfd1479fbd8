// `blaze run` with the spring laws in double (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_spring<double>(const blaze::Scene&, const blaze::app::Options&);
