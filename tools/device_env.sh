# Sourced by the scripts that run on the lent GPU machine (gpu_session.sh, gpu_suites.sh): no
# package registry there, so the GSL and toml++ .debs that `../shared/tools/device-deps.sh
# libtomlplusplus-dev` put in .devdeps/ (carried by the device call) are unpacked and put on the
# compiler's and loader's paths; `make` is told not to install anything.
export BLAZE_SKIP_DEPS=1 BLAZE_NO_MESHIO=1
if [ -d .devdeps ] && ! [ -e /usr/include/gsl/gsl_odeiv2.h ]; then
  mkdir -p /tmp/dd && for f in .devdeps/*.deb; do dpkg -x "$f" /tmp/dd; done
  export CPATH=/tmp/dd/usr/include${CPATH:+:$CPATH} LIBRARY_PATH=/tmp/dd/usr/lib/x86_64-linux-gnu${LIBRARY_PATH:+:$LIBRARY_PATH} \
         LD_LIBRARY_PATH=/tmp/dd/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
