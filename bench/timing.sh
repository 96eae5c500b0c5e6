# The bench scripts' shared timing helpers, sourced (never run): the median of numbers on stdin, and a whole
# process timed by bash's `time` as wall and CPU seconds (user + system, all threads: the steadier figure when
# other work shares the cores).
# shellcheck shell=bash
TIMEFORMAT='%3R %3U %3S'  # bash's time: wall, user, system
median() {
    sort -g | awk '{v[NR] = $1} END {if (NR % 2) print v[(NR + 1) / 2]; else printf "%.3f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}
timed() {  # time_file log_file command...: runs the command, writes "wall cpu" (cpu = user + system)
    local tfile=$1 log=$2 wall user sys
    shift 2
    { time "$@" > "$log" 2>&1; } 2> "$tfile" || return 1
    read -r wall user sys < "$tfile"
    awk -v w="$wall" -v u="$user" -v s="$sys" 'BEGIN {printf "%.3f %.3f\n", w, u + s}' > "$tfile"
}
