# What every tests/*_end_to_end.sh script shares, read with `. "$(dirname "$0")/end_to_end_lib.sh"`: a scratch
# directory $dir removed at exit, fail MESSAGE, and expect_exit CODE COMMAND....

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# expect_exit CODE COMMAND...: runs COMMAND, which must exit with CODE.
expect_exit() {
  want=$1
  shift
  set +e
  "$@"
  got=$?
  set -e
  [ "$got" -eq "$want" ] || fail "$* exited $got, expected $want"
}
