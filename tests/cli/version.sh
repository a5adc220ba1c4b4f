#!/usr/bin/env bash
# `lunaster --version` (and `lunaster version`) through the launcher: the version CMake's project()
# gives, the commit the build came from (git describe of the source tree, "unknown" outside a git
# checkout), the build type, and one line per library with its version; Lua's is the one of the
# lua.h lunaster was compiled with.
# Usage: version.sh LUNASTER SOURCE_DIR VERSION BUILD_TYPE LUA_INCLUDE_DIR
set -u
exe=$1; src=$2; version=$3; build_type=$4; lua_include=$5
fail() { echo "FAIL: $*"; exit 1; }

text=$("$exe" --version 2>&1); status=$?
echo "$text"
[ $status -eq 0 ] || fail "lunaster --version exited $status"
[ "$("$exe" version 2>&1)" = "$text" ] || fail "'lunaster version' differs from 'lunaster --version'"

line() { sed -n "$1p" <<<"$text"; }
[ "$(line 1)" = "lunaster $version" ] || fail "line 1 is '$(line 1)', expected 'lunaster $version'"
commit=unknown
if top=$(git -C "$src" rev-parse --show-toplevel 2>/dev/null) && [ "$(realpath "$top")" = "$(realpath "$src")" ]; then
  commit=$(git -C "$src" describe --always --dirty --abbrev=12 --exclude='*')
fi
# A tree edited since the build may differ by "-dirty": the commit itself must be the same.
[ "$(line 2 | sed 's/-dirty$//')" = "commit ${commit%-dirty}" ] ||
  fail "line 2 is '$(line 2)', the source tree is at commit $commit (rebuild after committing)"
[[ "$(line 3)" == "build $build_type, "* ]] || fail "line 3 is '$(line 3)', expected 'build $build_type, ...'"
[ "$(line 4)" = "libraries:" ] || fail "line 4 is '$(line 4)', expected 'libraries:'"

for name in MUMPS PETSc SuiteSparse CHOLMOD UMFPACK MED-file HDF5 Lua OpenBLAS Eigen "Open MPI"; do
  grep -Eq "^  $name +[0-9]+\.[0-9]+\.[0-9]+ +(run time|header): " <<<"$text" || fail "no version line for $name"
done
lua_release=$(awk '/#define[ \t]+LUA_VERSION_(MAJOR|MINOR|RELEASE)[ \t]/ { gsub(/"/, "", $3); v = v (v == "" ? "" : ".") $3 }
                   END { print v }' "$lua_include/lua.h")
grep -Eq "^  Lua +${lua_release//./\\.} +header: lua\.h" <<<"$text" || fail "the Lua line does not give $lua_release (lua.h)"
echo "PASS"
