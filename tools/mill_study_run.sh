# Sourced by the mill studies' scripts (tools/los_bronces.sh, tools/scaling_mill.sh):
#   mill_study_run SCENE DEFAULT_DIR STUDY_BINARY|--report [DIR] [--set key=value]...
# runs study_mill on SCENE into DIR (DEFAULT_DIR unless given), its output also in DIR/run.log,
# or with --report only sets DIR for the table to be made from a run's files; DIR is left in $dir.
mill_study_run() {
  local scene=$1 default_dir=$2 bin=$3
  shift 3
  dir=$default_dir
  if [ $# -ge 1 ] && [ "${1#--}" = "$1" ]; then dir=$1; shift; fi  # DIR, unless the options begin
  mkdir -p "$dir"
  if [ "$bin" != "--report" ]; then
    "$bin" "$scene" --set "output.directory=$dir" "$@" | tee "$dir/run.log"
  fi
}
