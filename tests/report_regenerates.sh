#!/usr/bin/env bash
# A report committed with its runs' files is what its script writes from them: the report folder is copied
# into a scratch tree laid out as the repository, the script run there with the report's own arguments, and
# the new report.md compared with the committed one (a report edited by hand, or a script changed without
# regenerating its report, fails here).
#   report_regenerates.sh SOURCE_DIR SCRATCH REPORT_DIR SCRIPT [ARG...]   (REPORT_DIR, SCRIPT, ARGs relative to
#   the repository root)
set -euo pipefail
src=$1 scratch=$2 report=$3 script=$4
shift 4
rm -rf "$scratch" && mkdir -p "$scratch/$(dirname "$report")" "$scratch/$(dirname "$script")"
cp -r "$src/$report" "$scratch/$report"
cp "$src/$(dirname "$script")"/*.py "$scratch/$(dirname "$script")/"  # the script and the modules beside it
rm "$scratch/$report/report.md"
(cd "$scratch" && python3 "$script" "$@" > /dev/null)
diff -u "$src/$report/report.md" "$scratch/$report/report.md" || { echo "$report/report.md is not what $script writes"; exit 1; }
