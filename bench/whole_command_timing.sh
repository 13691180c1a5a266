# Shared by the bench scripts that time whole commands (sourced, not run): a clock in seconds
# and the median of numbers read one a line.
now() { date +%s.%N; }
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
