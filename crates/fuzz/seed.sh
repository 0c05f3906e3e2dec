#!/usr/bin/env bash
# Seed the fuzz corpora: crates/fuzz/corpus/<target>/ (git-ignored) gets
#  - the real programs of ../shared/corpus (beside the repository; TAPEGATE_CORPUS overrides),
#    cut at line ends into pieces of at most 4 KB (libFuzzer's default -max_len) -- copied at
#    run time, never committed, since they are other people's files;
#  - the hand-written programs and expressions of crates/fuzz/seeds/.
# For tokenize, check and convert byte 0 of an input selects the dialect and the profile
# (src/lib.rs), so each piece is written behind a selector byte, the pieces cycling through
# four dialects and the four profile variants. The expr target gets the expressions: the
# hand-written ones and the bracketed and '=' values found in the real programs.
# Only seed-* files are (re)written: what libFuzzer added to a corpus is kept.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
shared=${TAPEGATE_CORPUS:-$root/../shared/corpus}
corpus=$here/corpus
pieces=$(mktemp -d)
trap 'rm -rf "$pieces"' EXIT

# Dialects (bits 0-5): everything allowed, ISO (expressions only), Fanuc macro (# [] * and
# expressions), and # [] ; with expressions.
dialects=(63 32 54 46)

selector() { # the selector byte of piece number $1
    local i=$1
    echo $(( dialects[(i / 4) % 4] | ((i % 4) << 6) ))
}

write_with_selector() { # selector, source file, destination
    printf "\\$(printf '%03o' "$1")" > "$3"
    cat "$2" >> "$3"
}

n=0
if [ -d "$shared" ]; then
    for f in "$shared"/*; do
        [ -f "$f" ] || continue
        case "$f" in *.md) continue ;; esac
        split -C 4096 -d -a 4 "$f" "$pieces/$(basename "$f")."
    done
else
    echo "seed.sh: no real corpus at $shared; seeding the hand-written programs only" >&2
fi
for f in "$here"/seeds/programs/*; do
    # Each hand-written program under every profile variant, all dialect flags on and ISO.
    for s in 63 127 191 255 32 160; do
        cp "$f" "$pieces/hand-$s-$(basename "$f")"
    done
done

for target in tokenize check convert; do
    mkdir -p "$corpus/$target"
    rm -f "$corpus/$target"/seed-*
done
i=0
for p in "$pieces"/*; do
    name=$(basename "$p")
    case "$name" in
        hand-*) s=${name#hand-}; s=${s%%-*} ;;
        *) s=$(selector "$i"); i=$((i + 1)) ;;
    esac
    for target in tokenize check convert; do
        write_with_selector "$s" "$p" "$corpus/$target/seed-$name"
    done
    n=$((n + 1))
done

mkdir -p "$corpus/expr"
rm -f "$corpus/expr"/seed-*
e=0
for f in "$here"/seeds/expr/*; do
    cp "$f" "$corpus/expr/seed-$(basename "$f")"
    e=$((e + 1))
done
if [ -d "$shared" ]; then
    # The values of '=' words and the bracketed groups of the real programs, once each.
    { grep -ahoE '=[^ ()=;]+' "$shared"/* 2>/dev/null | cut -c2- || true
      grep -ahoE '\[[^]();]*\]' "$shared"/* 2>/dev/null || true
    } | LC_ALL=C sort -u | head -n 400 > "$pieces/values"
    while IFS= read -r v; do
        e=$((e + 1))
        printf '%s' "$v" > "$corpus/expr/seed-value-$e"
    done < "$pieces/values"
fi
echo "seed.sh: $n program pieces each for tokenize, check and convert; $e expressions for expr"
