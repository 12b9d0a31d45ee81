# What the shipped plots read from a hillstab output file (plots/columns.gp calls it):
#   awk -v get=scene -v key=NAME -f header.awk FILE
#       the value of NAME in the effective scene of the header (the first '# &group ...'
#       line that gives it), quotes removed; a list gives its values joined by ', '
#   awk -v get=line -v key=KEY -f header.awk FILE
#       the text of the first header line '# KEY: ...' after 'KEY: '
#   awk -v get=range -v key=NAME -f header.awk FILE
#       the range of column NAME: NAME_min and NAME_max of the effective scene when it gives
#       both (alpha_min of &chart, a_min and omega_min of &physical, ...), else the smallest
#       and the largest value over the data lines (0 1 when there is none); widened by 0.5
#       each way when the two are equal, so that a range is never empty
#   awk -v get=values -v key=NAME -f header.awk FILE
#       the distinct values of column NAME in the order of the file, blank-separated
# Column names are those of the '# columns:' line; the header ends there.
function scene_value(line, name,    text, at, value) {
   text = " " substr(line, index(line, "&"))
   at = index(text, " " name " = ")
   if (at == 0) at = index(text, "," name " = ")
   if (at == 0) return ""
   value = substr(text, at + length(name) + 4)
   if (match(value, /, [A-Za-z_][A-Za-z_0-9]* = /)) value = substr(value, 1, RSTART - 1)
   else sub(/ *\/ *$/, "", value)
   gsub(/^'|'$/, "", value)
   return value
}
BEGIN { column = 0; n = 0; done = 0; scene_low = ""; scene_high = "" }
!header_done && /^# columns:/ {
   header_done = 1
   for (i = 3; i <= NF; i++) if ($i == key) column = i - 2
   if (get == "scene" || get == "line") exit
   if (get == "range" && scene_low != "" && scene_high != "") {
      n = 1; low = scene_low + 0; high = scene_high + 0
      exit
   }
   if (column == 0) exit
   next
}
!header_done && get == "range" && /^# &[A-Za-z_]+ / {
   if (scene_low == "") scene_low = scene_value($0, key "_min")
   if (scene_high == "") scene_high = scene_value($0, key "_max")
   next
}
!header_done {
   if (get == "scene" && /^# &[A-Za-z_]+ / && !done) {
      value = scene_value($0, key)
      if (value != "") {
         print value
         done = 1
         exit
      }
   }
   if (get == "line" && index($0, "# " key ": ") == 1 && !done) {
      print substr($0, length(key) + 5)
      done = 1
      exit
   }
   next
}
column > 0 && NF >= column && $1 !~ /^#/ {
   if (get == "range") {
      x = $column + 0
      if (n == 0 || x < low) low = x
      if (n == 0 || x > high) high = x
      n++
   } else if (get == "values" && !($column in seen)) {
      seen[$column] = 1
      list = list (n++ ? " " : "") $column
   }
}
END {
   if (get == "range") {
      if (n == 0) { low = 0; high = 1 }
      if (low == high) { low -= 0.5; high += 0.5 }
      printf "%.17g %.17g\n", low, high
   } else if (get == "values") {
      print list
   }
}
