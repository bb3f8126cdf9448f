# Shared by the gallery scripts (sourced): how a look ("toon+paper" or "preset:pencil") is
# named in file names, in the table and on nprgl's command line, and how a table replaces the
# part of README.md between its markers.
fileName() { case "$1" in preset:*) echo "preset-${1#preset:}" ;; *) echo "$1" | tr '+' '-' ;; esac; }
label() { case "$1" in preset:*) echo "--preset ${1#preset:}" ;; *) echo "$1" ;; esac; }
styleArgs() { case "$1" in preset:*) echo "--preset ${1#preset:}" ;; *) echo "--style $1" ;; esac; }

# replaceReadmeSection README MARKER TABLE_FILE: the text between <!-- MARKER:start --> and
# <!-- MARKER:end --> becomes the table's.
replaceReadmeSection() {
    python3 - "$1" "$2" "$3" <<'PY'
import sys
readme, marker, table = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
text = open(readme).read()
start, end = f"<!-- {marker}:start -->", f"<!-- {marker}:end -->"
if start not in text or end not in text:
    sys.exit(f"{readme} has no {marker} markers")
head, rest = text.split(start, 1)
tail = rest.split(end, 1)[1]
open(readme, "w").write(head + start + "\n" + table + end + tail)
PY
}
