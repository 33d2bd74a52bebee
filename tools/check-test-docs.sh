#!/usr/bin/env bash
# Every doc section a test message cites (`docs/NAME.md, \"Section\"` in
# tests/) must exist as a heading of that doc, so that a student sent there
# finds it (docs/testing.md, "Messages"). Usage: tools/check-test-docs.sh
# Exit status: 0 when every cited section exists, 1 otherwise.
set -uo pipefail
cd "$(dirname "$0")/.."
status=0
# The citations as written in C strings: docs/NAME.md, \"Section\"
while IFS=$'\t' read -r where doc section; do
  if [ ! -f "$doc" ]; then
    echo "$where: cites $doc, which does not exist"; status=1; continue
  fi
  if ! grep -qxF -e "## $section" -e "### $section" -e "# $section" "$doc"; then
    echo "$where: cites $doc, \"$section\": no such heading"; status=1
  fi
done < <(grep -noE 'docs/[A-Za-z0-9_.-]+\.md, \\"[^"\\]+\\"' tests/*.c tests/*.h |
         sed -E 's/^([^:]+:[0-9]+):(docs\/[^,]+), \\"(.*)\\"$/\1\t\2\t\3/')
[ "$status" = 0 ] && echo "check-test-docs: every doc section the tests cite exists"
exit $status
