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
# Open MPI for ranks sharing the GPU (issue 21): the lent machine has none. Its .debs travel in
# .devdeps too (`../shared/tools/device-deps.sh libtomlplusplus-dev openmpi-bin openmpi-common
# libopenmpi3 libopenmpi-dev libevent-core-2.1-7 libevent-pthreads-2.1-7 libevent-2.1-7 libfabric1
# libhwloc15 libpmix2 libucx0 libibverbs1 librdmacm1 libpsm2-2 libpsm-infinipath1 libnl-3-200
# libnl-route-3-200 libltdl7 libnuma1 libmunge2 libpciaccess0 libxnvctrl0`); unpacked under /tmp/dd,
# Open MPI finds its plugins and help files there through OPAL_PREFIX, and mpirun / mpicxx (Debian
# makes them alternatives, which dpkg -x does not) become links to orterun / opal_wrapper.
if ! command -v mpirun > /dev/null && [ -x /tmp/dd/usr/bin/orterun ]; then
  ln -sf orterun /tmp/dd/usr/bin/mpirun && ln -sf opal_wrapper /tmp/dd/usr/bin/mpicxx
  export OPAL_PREFIX=/tmp/dd/usr PATH=/tmp/dd/usr/bin:$PATH
fi
