#!/usr/bin/env bash
# Extracts the C example from README.md, checks it matches examples/readme_example.c, compiles it
# against the built static library and runs it.
set -euo pipefail
src="$1"; lib="$2"; out="$3"; san="${4:-OFF}"
extra=""
[ "$san" = "ON" ] && extra="-fsanitize=address,undefined"
mkdir -p "$out"
awk '/^```c$/{f=1;next} /^```$/{f=0} f' "$src/README.md" > "$out/readme_example.c"
diff -u "$src/examples/readme_example.c" "$out/readme_example.c"
cc -std=c17 -Wall -Wextra -Werror $extra -I"$src/include" "$out/readme_example.c" "$lib" $(pkg-config --libs gsl) -lm -o "$out/readme_example"
"$out/readme_example" | grep -q '^distance '
echo "README example: 1 passed, 0 failed"
