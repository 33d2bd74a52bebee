# A submission's region file with the regions of later steps stubbed, for the
# grader (tools/grading/one.sh; docs/grading.md, "How a submission is graded"):
# step N is graded with the student's regions of steps <= N when the whole
# file does not build.
# Usage: awk -v upto=N -f tools/grading/cut.awk STUB SUBMISSION
#   STUB        the starter's copy of the file (every region a TODO line and
#               its STUB line: tools/check/starter.sh DIR 1)
#   SUBMISSION  the student's copy, in the starter's markers
#                 /* BEGIN step NN: NAME */ ... /* END step NN */
# Prints SUBMISSION with the inside of each region of a step after N replaced
# by the inside of STUB's region of the same rank and step. Exits 3 when the
# two files' regions do not pair (a marker removed, moved or added): the
# caller then takes the file whole.

function begin_step(line) { sub(/.*\/\* BEGIN step /, "", line); return substr(line, 1, 2) }
function bad() { broken = 1; exit 3 }
FNR == 1 { file++ }
/\/\* BEGIN step [0-9][0-9]: .*\*\// {
  if (file == 1) { n1++; step1[n1] = begin_step($0); in1 = 1; body1[n1] = ""; next }
  if (in2) bad()
  n2++; in2 = 1
  if (n2 > n1 || step1[n2] != begin_step($0)) bad()
  cut = begin_step($0) + 0 > upto + 0
  out = out $0 "\n"
  if (cut) out = out body1[n2]
  next
}
/\/\* END step [0-9][0-9] \*\// {
  if (file == 1) { in1 = 0; next }
  if (!in2) bad()
  in2 = 0
  out = out $0 "\n"
  next
}
file == 1 { if (in1) body1[n1] = body1[n1] $0 "\n"; next }
in2 && cut { next }
{ out = out $0 "\n" }
END {
  if (broken) exit 3
  if (in2 || n2 != n1) exit 3
  printf "%s", out
}
