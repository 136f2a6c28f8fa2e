#!/bin/sh
# The install and the Debian package as docs/properties.md (Linking it) tells a user to make them, run by CI
# (.ci/run) on its clean clone:
#   install_end_to_end.sh SOURCE_DIR
# The commands of its install-commands and package-commands blocks run exactly as shown, from the repository's
# root, with HOME a scratch directory (so that ~/.local is in it). Then: the program installed runs, and was
# built for any x86-64 (no 256-bit AVX register in its code); the package unpacked into a clean root (dpkg -x)
# holds the same files under /usr, declares its dependencies and licence, and its program runs; tests/consumer/
# builds against the package alone and passes.
set -eu
source_dir=$(cd "$1" && pwd)
. "$(dirname "$0")/end_to_end_lib.sh"
. "$(dirname "$0")/consumer_lib.sh"

# commands MARK: the lines of the ```sh block after <!-- MARK --> in docs/properties.md, list indentation removed.
commands() {
  awk -v mark="<!-- $1 -->" 'index($0, mark) {found = 1; next}
    found && !open && /^ *```sh/ {open = 1; next}
    open && /^ *```/ {exit}
    open {sub(/^   /, ""); print}' "$source_dir/docs/properties.md"
}
# run_block MARK: runs the block's commands in the repository's root, each echoed first, timed.
run_block() {
  block=$(commands "$1")
  [ -n "$block" ] || fail "docs/properties.md has no sh block after <!-- $1 -->"
  start=$(date +%s)
  (cd "$source_dir" && printf '%s\n' "$block" | while IFS= read -r line; do
    echo "+ $line"
    sh -euc "$line" || exit 1
  done) || fail "a command of <!-- $1 --> failed"
  echo "($1: $(($(date +%s) - start)) s)"
}

HOME=$dir/home
export HOME
mkdir -p "$HOME"
run_block install-commands
prefix=$HOME/.local
check_program "$prefix"
if objdump -d --no-show-raw-insn "$prefix/bin/circles" | grep -q '%ymm'; then
  fail "$prefix/bin/circles uses 256-bit AVX registers: it is not built for any x86-64"
fi

run_block package-commands
set -- "$source_dir"/build-install/circles_*.deb
[ $# -eq 1 ] && [ -f "$1" ] || fail "not one package in build-install/: $*"
deb=$1
echo "$deb:"
dpkg-deb --field "$deb" Package Version Architecture Depends Recommends
dpkg-deb --field "$deb" Depends | grep -q 'libcairo2' ||
  fail "the package's Depends does not list the program's shared libraries: $(dpkg-deb --field "$deb" Depends)"
dpkg -x "$deb" "$dir/unpacked"
(cd "$prefix" && find . -type f | sort) >"$dir/installed"
(cd "$dir/unpacked/usr" && find . -type f | sort) >"$dir/packaged"
diff "$dir/installed" "$dir/packaged" || fail "the package's files differ from those cmake --install installs"
check_program "$dir/unpacked/usr"
check_consumer "$dir/unpacked/usr" c++
echo "the package $deb: circles --version, the licence and the consumer project pass"
