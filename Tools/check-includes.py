#!/usr/bin/env python3
"""Fails when production code includes a layer its row of Documentation/Architecture.md's table
("What may include what") does not name, so that the table is the rule and not a wish.

    check-includes.py [ROOT]          exit 0: every include allowed; 1: forbidden includes, listed

Reads the table from the page itself. Each row names a layer (`Core`, `IO/Scene`, `Apps`, ...)
and the layers it may use, each with everything that layer may use in turn (a header of a layer
named there brings its own includes along): a layer's own files may always include each other;
"X and below" says the same of X; "everything above" is every layer of `Library/`; a
layer inside `IO` may be named without the prefix (`InputChecks` is `IO/InputChecks`). Words that
name no layer (the standard library, third-party SDKs, remarks) are left to the compiler. A row
that says "(the IO layers in its `.cpp` files)" lets only that layer's source files, not its
headers, include the IO layers. Tests (`Testing/` folders) are not production code and are not
checked. Only quoted project includes (`#include "Proxy/ProxySolver.h"`) are layer crossings;
a quoted include of a file beside the includer stays within its layer."""
import pathlib
import re
import sys

TABLE_START = "| layer | may include |"
SOURCE_SUFFIXES = {".h", ".cpp", ".cxx", ".hpp"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def read_table(page):
    rows = {}
    lines = page.read_text(encoding="utf-8").splitlines()
    try:
        start = lines.index(TABLE_START)
    except ValueError:
        sys.exit("check-includes: %s has no table headed %r" % (page, TABLE_START))
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if len(cells) != 2:
            sys.exit("check-includes: %s: a row of the table is not two cells: %s" % (page, line))
        rows[cells[0]] = cells[1]
    return rows


def library_layers(root):
    layers = set()
    for folder in sorted((root / "Library").iterdir()):
        if not folder.is_dir():
            continue
        if folder.name == "IO":
            layers.update("IO/" + sub.name for sub in folder.iterdir()
                          if sub.is_dir() and sub.name != "Testing")
        else:
            layers.add(folder.name)
    return layers


def resolve(name, known):
    """The layer a table word names, or None for a word that names no layer."""
    name = name.strip().strip("`")
    if name in known:
        return name
    if "IO/" + name in known:
        return "IO/" + name
    return None


def allowed_layers(rows, known):
    """Each layer's allowed set, with "and below" and "everything above" expanded."""
    direct = {}
    for layer, text in rows.items():
        names = set()
        if "everything above" in text:
            names.update(known)
        # Drop parenthesised remarks, then split on commas and semicolons.
        for word in re.split(r"[,;]", re.sub(r"\([^)]*\)", "", text)):
            word = word.strip()
            match = re.match(r"(.+?) and below$", word)
            if match:
                target = resolve(match.group(1), known)
                if target:
                    names.add(target)
                continue
            target = resolve(word, known | set(rows))
            if target:
                names.add(target)
        direct[layer] = names

    def expand(layer, seen):
        result = set(direct.get(layer, ()))
        for target in direct.get(layer, ()):
            if target not in seen:
                result |= expand(target, seen | {target})
        return result

    return {layer: expand(layer, {layer}) | {layer} for layer in rows}


def layer_of_file(path, root):
    """The table's layer of a production file, or None for files the table does not cover."""
    parts = path.relative_to(root).parts
    if "Testing" in parts:
        return None
    if parts[0] == "Library" and len(parts) > 2:
        return "IO/" + parts[2] if parts[1] == "IO" and len(parts) > 3 else parts[1]
    if parts[0] == "Apps":
        return "Apps"
    if parts[0] == "Wrapping" and len(parts) > 2:
        return "Wrapping/" + parts[1]
    return None


def layer_of_include(include, known):
    parts = include.split("/")
    if parts[0] == "IO" and len(parts) > 2 and "IO/" + parts[1] in known:
        return "IO/" + parts[1]
    if parts[0] in known and len(parts) > 1:
        return parts[0]
    return None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    page = root / "Documentation" / "Architecture.md"
    rows = read_table(page)
    known = library_layers(root)
    missing = sorted(layer for layer in known if layer not in rows)
    if missing:
        print("check-includes: %s: the table has no row for %s" % (page, ", ".join(missing)))
        return 1
    allowed = allowed_layers(rows, known)
    headers_only_own_io = {layer for layer, text in rows.items()
                           if "(the IO layers in its `.cpp` files)" in text}
    problems = []
    checked = 0
    for folder in ("Library", "Apps", "Wrapping"):
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
                continue
            layer = layer_of_file(path, root)
            if layer is None or layer not in rows:
                continue
            checked += 1
            text = path.read_text(encoding="utf-8", errors="replace")
            for match in INCLUDE.finditer(text):
                target = layer_of_include(match.group(1), known)
                if target is None or target == layer:
                    continue
                line = text.count("\n", 0, match.start()) + 1
                where = "%s:%d" % (path.relative_to(root), line)
                if target not in allowed[layer]:
                    problems.append("%s: %s may not include %s (%s)"
                                    % (where, layer, target, match.group(1)))
                elif (layer in headers_only_own_io and target.startswith("IO/")
                      and path.suffix in (".h", ".hpp") and "Private" not in path.parts):
                    problems.append("%s: %s includes %s in a header; only its .cpp files may"
                                    % (where, layer, target))
    for problem in problems:
        print(problem)
    if problems:
        print("check-includes: %d forbidden includes in %d files checked; the table is %s"
              % (len(problems), checked, page.relative_to(root)))
        return 1
    print("check-includes: %d files, every include allowed by %s"
          % (checked, page.relative_to(root)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
