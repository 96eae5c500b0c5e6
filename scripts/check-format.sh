#!/usr/bin/env bash
# Checks that every tracked C++ file (*.cpp, *.h, *.inc) is formatted as .clang-format says, with Debian 12's
# clang-format 14 (the version the tree was formatted with: other versions break some lines differently).
# Changes nothing; on a difference it lists the files and the command that fixes them, and exits 1.
# CLANG_FORMAT names another binary (then its version is not checked).
set -euo pipefail
cd "$(dirname "$0")/.."

if [[ -n "${CLANG_FORMAT:-}" ]]; then
  clang_format=$CLANG_FORMAT
else
  clang_format=$(command -v clang-format-14 || command -v clang-format || true)
  if [[ -z "$clang_format" ]]; then
    echo "check-format: clang-format not found (Debian package clang-format; scripts/install-deps.sh installs it)" >&2
    exit 1
  fi
  version=$("$clang_format" --version)
  if [[ ! "$version" =~ version\ 14\. ]]; then
    echo "check-format: $clang_format is '$version'; the tree is formatted with clang-format 14" \
      "(set CLANG_FORMAT to use this one anyway)" >&2
    exit 1
  fi
fi

mapfile -d '' files < <(git ls-files -z -- '*.cpp' '*.h' '*.inc')
if [[ ${#files[@]} -eq 0 ]]; then
  echo "check-format: git ls-files found no C++ files; is this a git checkout?" >&2
  exit 1
fi

# --dry-run --Werror reports every place that would change as "file:line:col: error: ..." and exits non-zero; it
# goes on through all the files, so one call names every file that differs.
report=$("$clang_format" --dry-run --Werror --style=file "${files[@]}" 2>&1) && status=0 || status=$?
if [[ $status -eq 0 ]]; then
  echo "check-format: ${#files[@]} files formatted as .clang-format says"
  exit 0
fi
mapfile -t bad < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' <<<"$report" | sort -u)
if [[ ${#bad[@]} -eq 0 ]]; then
  echo "check-format: $clang_format failed (exit $status):" >&2
  printf '%s\n' "$report" | head -n 20 >&2
  exit 1
fi
echo "check-format: ${#bad[@]} of ${#files[@]} files differ from .clang-format:" >&2
printf '  %s\n' "${bad[@]}" >&2
echo "Fix them with: $clang_format -i ${bad[*]}" >&2
exit 1
