#!/usr/bin/env bash
# Apply one mutant of tools/check/mutants/ (a realistic student bug, or a correct
# alternative) to a copy of the tree, in every file that carries its code.
# Usage: tools/check/mutate.sh ID DIR    apply tools/check/mutants/ID.mut to the tree DIR
#        tools/check/mutate.sh --list    every mutant: ID, step, kind, what
# Prints the files it changed. Exit 1, changing nothing, when a 'from' text is
# not exactly once in every file its glob names (the code moved on: update the
# mutant). The format is in tools/check/mutants/README.md; docs/testing-the-tests.md.
set -euo pipefail

usage() { echo "usage: tools/check/mutate.sh ID DIR | --list" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
mutants=$here/mutants

if [ "${1:-}" = --list ]; then
  [ $# -eq 1 ] || usage
  for m in "$mutants"/*.mut; do
    awk -v id="$(basename "$m" .mut)" '
      /^@@/ { exit } /^step:/ { s = $2 } /^kind:/ { k = $2 }
      /^what:/ { w = $0; sub(/^what:[ \t]*/, "", w) }
      END { printf "%s\t%s\t%s\t%s\n", id, s, k, w }' "$m"
  done
  exit 0
fi
[ $# -eq 2 ] || usage
id=$1 dir=$2
[ -f "$mutants/$id.mut" ] || { echo "mutate: no mutant '$id' (tools/check/mutate.sh --list names them)" >&2; exit 2; }
[ -d "$dir" ] || { echo "mutate: no directory '$dir'" >&2; exit 2; }

(cd "$here/../.." && perl - "tools/check/mutants/$id.mut" "$(realpath "$dir")" "$id") <<'PERL'
use strict;
use warnings;
my ($mut, $dir, $id) = @ARGV;
sub fail { print STDERR "mutate: $id: @_\n"; exit 1; }

# Parse: header lines "key: value", then hunks "@@ from" ... "@@ to" ... "@@ end",
# each applied to the files of the last "file:" line before it.
open(my $in, '<', $mut) or fail("cannot read $mut: $!");
my (%head, @hunks, $glob, $part, $from, $to, $at);
while (my $line = <$in>) {
  if (defined $part) {
    if ($line =~ /^\@\@ to\s*$/ && $part eq 'from') { $part = 'to'; next; }
    if ($line =~ /^\@\@ end\s*$/ && $part eq 'to') {
      push @hunks, { glob => $glob, from => $from, to => $to, line => $at };
      undef $part; next;
    }
    fail("$mut:$.: '\@\@ $1' out of order") if $line =~ /^\@\@ (\w+)/;
    if ($part eq 'from') { $from .= $line } else { $to .= $line }
    next;
  }
  next if $line =~ /^\s*(#|$)/;
  if ($line =~ /^\@\@ from\s*$/) {
    fail("$mut:$.: a hunk before any 'file:' line") unless defined $glob;
    ($part, $from, $to, $at) = ('from', '', '', $.); next;
  }
  if ($line =~ /^(\w+):\s*(.*?)\s*$/) {
    if ($1 eq 'file') { $glob = $2 } else { $head{$1} = $2 }
    next;
  }
  fail("$mut:$.: expected 'key: value' or '\@\@ from', found: $line");
}
fail("$mut: a hunk never ends ('\@\@ end')") if defined $part;
fail("$mut: no hunk") unless @hunks;
for my $k ('step', 'kind', 'what') { fail("$mut: no '$k:' line") unless defined $head{$k}; }
fail("$mut: kind must be 'bug', 'alternative' or 'alternative-unrefined'")
  unless $head{kind} =~ /^(bug|alternative|alternative-unrefined)$/;

# Apply every hunk in memory first: nothing is written unless all match.
my (%text, @order);
for my $h (@hunks) {
  my @files = sort grep { -f } glob("$dir/$h->{glob}");
  fail("hunk of line $h->{line}: no file matches '$h->{glob}' in $dir") unless @files;
  for my $f (@files) {
    unless (exists $text{$f}) {
      open(my $fh, '<', $f) or fail("cannot read $f: $!");
      local $/; $text{$f} = <$fh>; push @order, $f;
    }
    my $n = () = $text{$f} =~ /\Q$h->{from}\E/g;
    (my $rel = $f) =~ s/^\Q$dir\E\/?//;
    fail("$rel: the 'from' text of the hunk at $mut:$h->{line} is " .
         ($n ? "there $n times" : "not there") . " (the code changed? update the mutant)")
      unless $n == 1;
    $text{$f} =~ s/\Q$h->{from}\E/$h->{to}/;
  }
}
for my $f (@order) {
  open(my $fh, '>', $f) or fail("cannot write $f: $!");
  print $fh $text{$f};
  close($fh) or fail("cannot write $f: $!");
  (my $rel = $f) =~ s/^\Q$dir\E\/?//;
  print "$rel\n";
}
PERL
