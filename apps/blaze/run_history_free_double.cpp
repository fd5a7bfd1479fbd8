// `blaze run` with the history free laws in double (apps/blaze/run_scene.hpp).
#include "apps/blaze/run_scene.hpp"

template int blaze::app::run_history_free<double>(const blaze::Scene&, const blaze::app::Options&);
