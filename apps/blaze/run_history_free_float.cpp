// `blaze run` with the history free laws in float (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_history_free<float>(const blaze::Scene&, const blaze::app::Options&);
