#!/usr/bin/env bash
# Checks the layering of lib/ (lib/layers.txt): every `#include "folder/..."` of a file in
# lib/ names a folder of the file's own layer or of a lower one (never app/), every folder
# is in exactly one layer, and the include graph between folders has no cycle.
# With --build DIR it also checks the layer libraries built in DIR: no layer's library
# needs a symbol that only a higher layer's library defines.
#
# Usage: scripts/check-layers.sh [--graph] [--build BUILD_DIR]
#   --graph   print the include graph between folders ("from -> to (count)") and stop
# Exit status: 0 when the layering holds, 1 when it does not (each violation is listed),
# 2 on a usage error.
set -euo pipefail
cd "$(dirname "$0")/.."

graph_only=0
build=
while [ $# -gt 0 ]; do
    case "$1" in
        --graph) graph_only=1 ;;
        --build) build=${2:?--build needs a directory}; shift ;;
        *) echo "usage: $0 [--graph] [--build BUILD_DIR]" >&2; exit 2 ;;
    esac
    shift
done

layers_file=lib/layers.txt
# The folders live in lib/ and are included as "folder/x.hpp", or (after the move under a
# prefix) in lib/gearloss/ and are included as "gearloss/folder/x.hpp".
root=lib
prefix=
if [ -d lib/gearloss ]; then
    root=lib/gearloss
    prefix=gearloss/
fi

declare -A layer_of rank_of
layers=()
while IFS= read -r line; do
    case "$line" in ''|'#'*) continue ;; esac
    name=${line%%:*}
    layers+=("$name")
    rank_of[$name]=${#layers[@]}
    for f in ${line#*:}; do
        if [ -n "${layer_of[$f]:-}" ]; then
            echo "check-layers: folder '$f' is in two layers (${layer_of[$f]}, $name) in $layers_file" >&2
            exit 1
        fi
        layer_of[$f]=$name
    done
done < "$layers_file"

fail=0
report() { echo "LAYERS: $*"; fail=1; }

# Folders of app/ (a library file must not include them).
declare -A app_folder
for d in app/*/; do
    [ -d "$d" ] || continue
    d=${d%/}; app_folder[${d##*/}]=1
done

# FILE LINE FOLDER-OF-FILE INCLUDED-FOLDER INCLUDED-PATH, one row per include of a file of
# lib/ that names a folder ("a/b.hpp" or <a/b.hpp>); includes without a folder are local.
edges=$(find "$root" -mindepth 2 -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' -o -name '*.inc' \) | sort |
    while IFS= read -r file; do
        rel=${file#"$root"/}
        from=${rel%%/*}
        { grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*["<][^">]+[">]' "$file" || true; } |
            sed -E 's/^([0-9]+):[^"<]*["<]([^">]+)[">].*/\1 \2/' |
            while read -r n path; do
                p=$path
                if [ -n "$prefix" ]; then
                    case "$p" in "$prefix"*) p=${p#"$prefix"} ;; *) [[ "$p" == */* ]] && ! [ -d "$root/${p%%/*}" ] && continue ;; esac
                fi
                [[ "$p" == */* ]] || continue
                echo "$file $n $from ${p%%/*} $path"
            done
    done)

# The include graph between folders: "count from to" per edge.
folder_edges=$(while read -r file n from to path; do
    if [ -n "$file" ] && [ "$from" != "$to" ] && [ -d "$root/$to" ]; then echo "$from $to"; fi
done <<< "$edges" | sort | uniq -c)

if [ "$graph_only" = 1 ]; then
    echo "$folder_edges" | awk 'NF == 3 {print $2 " -> " $3 " (" $1 ")"}'
    exit 0
fi

# Every folder of the library is in a layer and every layer's folder exists.
for d in "$root"/*/; do
    d=${d%/}; d=${d##*/}
    [ -n "${layer_of[$d]:-}" ] || report "folder $root/$d is in no layer of $layers_file"
done
for f in "${!layer_of[@]}"; do
    [ -d "$root/$f" ] || report "folder '$f' of $layers_file does not exist in $root/"
done

while read -r file n from to path; do
    [ -n "$file" ] || continue
    if [ -n "${app_folder[$to]:-}" ] && [ -z "${layer_of[$to]:-}" ]; then
        report "$file:$n: includes \"$path\" of app/"
        continue
    fi
    [ -n "${layer_of[$to]:-}" ] || continue  # a system or third-party header ("fmt/format.h")
    [ -n "${layer_of[$from]:-}" ] || continue  # reported above
    if [ "${rank_of[${layer_of[$to]}]}" -gt "${rank_of[${layer_of[$from]}]}" ]; then
        report "$file:$n: $from (layer ${layer_of[$from]}) includes \"$path\" of the higher layer ${layer_of[$to]}"
    fi
done <<< "$edges"

# Cycles: the strongly connected components of the folder graph (Tarjan) with more than one
# folder, each with one include of every edge inside it.
sccs=$(echo "$folder_edges" | awk '
    NF == 3 { a = $2; b = $3; adj[a] = adj[a] " " b; node[a]; node[b] }
    function visit(v,   ws, nw, i, w) {
        index_[v] = lowlink[v] = ++counter; stack[++sp] = v; onstack[v] = 1
        nw = split(adj[v], ws, " ")
        for (i = 1; i <= nw; i++) {
            w = ws[i]
            if (!(w in index_)) { visit(w); if (lowlink[w] < lowlink[v]) lowlink[v] = lowlink[w] }
            else if (onstack[w] && index_[w] < lowlink[v]) lowlink[v] = index_[w]
        }
        if (lowlink[v] == index_[v]) {
            comp = ""; n = 0
            do { w = stack[sp--]; onstack[w] = 0; comp = comp " " w; n++ } while (w != v)
            if (n > 1) print substr(comp, 2)
        }
    }
    END { for (v in node) if (!(v in index_)) visit(v) }')
if [ -n "$sccs" ]; then
    while read -r comp; do
        report "include cycle between the folders: $comp"
        while read -r file n from to path; do
            case " $comp " in *" $from "*) ;; *) continue ;; esac
            case " $comp " in *" $to "*) ;; *) continue ;; esac
            if [ "$from" != "$to" ]; then echo "$from -> $to: $file:$n \"$path\""; fi
        done <<< "$edges" | awk '!seen[$1 $3]++' | sed 's/^/    /'
    done <<< "$sccs"
fi

# Link check: the undefined symbols of each layer's library defined by no library of its own
# or a lower layer but by a higher one.
if [ -n "$build" ]; then
    defined() { nm -P --defined-only "$1" 2>/dev/null | awk '$2 ~ /^[TtDdBbRrVvWwiu]$/ {print $1}' | sort -u; }
    for l in "${layers[@]}"; do
        lib=$(find "$build" -name "libgearloss_$l.a" -print -quit)
        if [ -z "$lib" ]; then report "no libgearloss_$l.a in $build"; continue; fi
        libs[${rank_of[$l]}]=$lib
    done
    if [ "$fail" = 0 ]; then
        tmpd=$(mktemp -d)
        trap 'rm -rf "$tmpd"' EXIT
        for l in "${layers[@]}"; do defined "${libs[${rank_of[$l]}]}" > "$tmpd/def.$l"; done
        for l in "${layers[@]}"; do
            r=${rank_of[$l]}
            nm -P --undefined-only "${libs[$r]}" 2>/dev/null | awk 'NF >= 2 {print $1}' | sort -u > "$tmpd/undef"
            : > "$tmpd/below"
            for m in "${layers[@]}"; do
                if [ "${rank_of[$m]}" -le "$r" ]; then cat "$tmpd/def.$m" >> "$tmpd/below"; fi
            done
            sort -u -o "$tmpd/below" "$tmpd/below"
            comm -23 "$tmpd/undef" "$tmpd/below" > "$tmpd/missing"
            for m in "${layers[@]}"; do
                [ "${rank_of[$m]}" -gt "$r" ] || continue
                comm -12 "$tmpd/missing" "$tmpd/def.$m" | while read -r s; do
                    echo "LAYERS: libgearloss_$l.a needs $(echo "$s" | c++filt) of the higher layer $m"
                done > "$tmpd/up"
                if [ -s "$tmpd/up" ]; then cat "$tmpd/up"; fail=1; fi
            done
        done
    fi
fi

if [ "$fail" = 0 ]; then
    echo "layers ok: ${layers[*]} (lowest first), $(echo "$folder_edges" | awk 'NF == 3' | wc -l) include edges between ${#layer_of[@]} folders, no cycle"
fi
exit "$fail"
