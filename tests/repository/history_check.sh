#!/usr/bin/env bash
# history_check.sh PROJECT_DIR: the project's text files (tracked, and new
# ones git does not ignore) say what the code is, not when or under which
# work item it came to be. It prints file:line:text for each line that
#   (a) dates something by a unit of work (the words are in s_* below): an
#       ordinal word or number before a session or sitting; a number after a
#       session, sitting, round or stop; an ordinal from the eleventh up
#       before a round, stop or pass. An algorithm's first pass or second
#       round is a description and passes; an ordinal in the twenties is a
#       date;
#   (b) cites an issue or pull request by number, or a number after a hash
#       sign that follows a space or bracket (colours such as #404040 have
#       six digits and pass).
# Binary files and third_party/ (other projects' code) are skipped.
# Exit 0: no hit; 1: hits; 77: PROJECT_DIR is not a git work tree (ctest
# marks the test skipped).
#
# history_check.sh --self-test: runs the check on a temporary repository
# with one line of each kind it must report and lines it must accept.
#
# Every pattern is assembled from pieces below, so this file never matches
# itself.
set -uo pipefail

# The words a pattern is made of, split so that no literal in this file reads
# as a hit.
s_ses="ses""sion" s_sit="sit""ting" s_rnd="rou""nd" s_stp="st""op"
s_pas="pa""ss" s_iss="is""sue" s_pr="pull req""uest"
units_always="(${s_ses}|${s_sit})"       # always units of work
units_any="(${s_ses}|${s_sit}|${s_rnd}|${s_stp})"
units_ambiguous="(${s_rnd}|${s_stp}|${s_pas})"  # also words of algorithms

small="first|second|third|fourth|fifth|sixth|seventh|eighth|ninth|tenth"
teen="eleventh|twelfth|(thir|four|fif|six|seven|eigh|nine)teenth"
tens_card="twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety"
tens_ord="twentieth|thirtieth|fortieth|fiftieth|sixtieth|seventieth|eightieth|ninetieth"
compound="(${tens_card})[- ]?(${small})"
big_word="${teen}|${tens_ord}|${compound}"
num_any="[0-9]+(st|nd|rd|th)"
num_big="[0-9]{2,}(st|nd|rd|th)"
b='(^|[^[:alnum:]_])'                    # start of a word
e='([^[:alnum:]_]|$)'                    # end of a word
sep="[- ]+"

pat_a1="${b}(${small}|${big_word}|${num_any})${sep}${units_always}"
pat_a2="${b}${units_any}(e?s)?${sep}(no\\.? ?|#)?[0-9]+${e}"
pat_a3="${b}(${big_word}|${num_big})${sep}${units_ambiguous}"
pat_b1="${b}(${s_iss}s?|${s_pr}s?|PRs?)${sep}(no\\.? ?)?#?[0-9]+${e}"
pat_b2="(^|[[:space:]([,;])#[0-9]{1,5}([^[:alnum:]_]|$)"
patterns=("$pat_a1" "$pat_a2" "$pat_a3" "$pat_b1" "$pat_b2")

# scan DIR: prints every hit in DIR's files; returns 1 when any. A comment
# line, and any line of a .md, .txt or .rst file, is also read joined to the
# last words of the prose before it (comment marks left out), so that a
# phrase broken across two lines is found too.
scan() {
  local dir=$1
  (cd "$dir" &&
   git ls-files -z --cached --others --exclude-standard -- . ':(exclude)third_party/**' |
   HC_PATTERNS=$(printf '%s\n' "${patterns[@]}") perl -0 -ne '
     BEGIN { @re = map { qr/$_/i } split /\n/, $ENV{HC_PATTERNS}; $hits = 0; }
     chomp; my $file = $_;
     next unless -f $file && open(my $fh, "<", $file);
     binmode $fh; my $head = ""; read($fh, $head, 8192); seek($fh, 0, 0);
     if ($head =~ /\0/) { close $fh; next; }
     # Prose files run on from line to line; in code, a comment runs on
     # where the next line is a comment line (not code after a comment).
     my $prose = $file =~ /\.(md|txt|rst)\z/i;
     my ($n, $tail) = (0, "");
     local $/ = "\n";
     while (my $line = <$fh>) {
       $n++; $line =~ s/\r?\n\z//;
       my $marked = $line =~ m{^\s*(//|/\*|\*|#|--|;|%)};
       my $body = $line; $body =~ s{^\s*(//+|/?\*+|#+|--|;+|%+)?\s*}{};
       my $joined = ($prose || $marked) && $tail ne "" ? "$tail $body" : "";
       # A phrase across the break: the joined text matches, the words of
       # the line before alone (reported there) do not.
       if (grep { $line =~ $_ } @re
           or ($joined ne "" and grep { $joined =~ $_ } @re and not grep { $tail =~ $_ } @re)) {
         print "$file:$n:$line\n"; $hits++;
       }
       # The last words of a line that holds prose: a comment, or any line
       # of a prose file.
       my $text = $prose ? $line : $line =~ m{(//|/\*|#|--)(.*)\z} ? $2 : $marked ? $body : "";
       my @w = split " ", $text; $tail = @w ? join(" ", @w[($#w > 2 ? $#w - 2 : 0) .. $#w]) : "";
     }
     close $fh;
     END { exit($hits ? 1 : 0); }')
}

# self_test: in a subshell, which removes its temporary repository on exit.
self_test() (
  command -v git >/dev/null || { echo "git is not installed"; exit 77; }
  status=0
  tmp=$(mktemp -d) || exit 1
  trap 'rm -rf "$tmp"' EXIT
  git -C "$tmp" init -q || exit 1
  # Each bad line alone in a file; check that it is reported, then that the
  # good lines are not.
  bad=(
    "// the seventeenth ${s_ses}'s encoder"
    "// measured in the twenty-fifth ${s_rnd}"
    "# ${s_ses} 12 sped this up"
    "// see ${s_stp} 46"
    "// the 21st ${s_sit}"
    "// fixes ${s_iss} 47"
    "// ${s_iss}s 48 and 49"
    "// (#""12) and ${s_iss} #""47"
    "see #""47 for the crash"
    $'// as the twenty-fourth\n// '"${s_ses}"' measured'
    $'Measured in the twenty-fifth\n'"${s_ses}"' (prose: a .md file).'
  )
  good=(
    "// the first ${s_pas} collects the edges, the second ${s_pas} ranks them"
    "// a second ${s_rnd} of the search widens the ball"
    "colour #404040: a component's start triangle"
    "// the tex#1.png file and ${s_iss}623.ply"
    "// passes 1 when one thread"
    "{1, 2, 3,  // face 2 repeated the other way round"
    " 0, 1, 2,  // face 0 repeated"
  )
  i=0
  for line in "${bad[@]}"; do
    rm -f "$tmp"/bad* "$tmp"/good*
    case $line in *prose*) name=bad$i.md ;; *) name=bad$i.cpp ;; esac
    printf 'a good line\n%s\n' "$line" >"$tmp/$name"
    git -C "$tmp" add -A >/dev/null
    if scan "$tmp" >/dev/null; then
      echo "self-test: not reported: $line"
      status=1
    fi
    i=$((i + 1))
  done
  rm -f "$tmp"/bad* "$tmp"/good*
  printf '%s\n' "${good[@]}" >"$tmp/good.cpp"
  mkdir -p "$tmp/third_party"
  printf '%s\n' "${bad[0]}" >"$tmp/third_party/other.txt"
  printf '\0%s\n' "${bad[0]}" >"$tmp/binary.dat"
  git -C "$tmp" add -A >/dev/null
  if ! scan "$tmp"; then
    echo "self-test: the lines above are reported but acceptable"
    status=1
  fi
  [ $status = 0 ] && echo "self-test: ${#bad[@]} bad lines reported, ${#good[@]} good lines, third_party/ and a binary file accepted"
  exit $status
)

if [ "${1:-}" = --self-test ]; then
  self_test
  exit $?
fi
if [ $# != 1 ]; then
  echo "usage: history_check.sh PROJECT_DIR | --self-test" >&2
  exit 2
fi
project=$1
if ! command -v git >/dev/null ||
   [ "$(git -C "$project" rev-parse --is-inside-work-tree 2>/dev/null)" != true ]; then
  echo "$project is not a git work tree: nothing to check"
  exit 77
fi
top=$(git -C "$project" rev-parse --show-toplevel)
scan "$top"
status=$?
if [ $status = 0 ]; then
  echo "no line dates work by sessions or rounds, none cites an issue number"
  exit 0
elif [ $status != 1 ]; then
  echo "the scan itself failed (exit $status): are git and perl installed?"
  exit 2
fi
echo "the lines above date work by sessions or rounds or cite issue numbers:"
echo "say what the code does and why, in the present tense (docs/tuning.md"
echo "holds the measured effect of each tuning constant)"
exit 1
