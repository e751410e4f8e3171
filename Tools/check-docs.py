#!/usr/bin/env python3
"""Fails on a damaged or broken Markdown page: a page over 200 KB, a block of
three or more lines repeated more than 50 times (a hand edit once pasted a table between every
character of a 136-line page), or a relative link to a file that does not exist; and a table of
the trace's flags in Documentation/CommandLine.md that differs from the tick conditions
Library/Core/TickConditions.h defines (their bits and their names). Reads the pages git tracks;
prints one line per defect naming the page, and exits 1 if there is any.

Usage: /usr/bin/python3 Tools/check-docs.py [repository root]"""
import collections
import pathlib
import re
import subprocess
import sys

MAX_BYTES = 200 * 1024
MAX_REPEATS = 50
BLOCK_LINES = 3
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CONDITIONS_HEADER = pathlib.Path("Library/Core/TickConditions.h")
FLAGS_PAGE = pathlib.Path("Documentation/CommandLine.md")
FLAGS_TABLE_HEAD = "| bit | value | name | the tick ... |"


def tracked_pages(root):
    listing = subprocess.run(["git", "-C", str(root), "ls-files", "*.md"], check=True,
                             capture_output=True, text=True).stdout
    return [root / line for line in listing.splitlines() if line]


def defects(page, root):
    found = []
    size = page.stat().st_size
    if size > MAX_BYTES:
        found.append(f"{size} bytes, more than {MAX_BYTES}: probably damaged by an edit")
    lines = page.read_text(encoding="utf-8", errors="replace").splitlines()
    blocks = collections.Counter(
        tuple(lines[i:i + BLOCK_LINES]) for i in range(len(lines) - BLOCK_LINES + 1)
        if all(line.strip() for line in lines[i:i + BLOCK_LINES]))
    for block, count in blocks.items():
        if count > MAX_REPEATS:
            found.append(f"a block of {BLOCK_LINES} lines repeated {count} times, starting "
                         f"'{block[0][:60]}'")
            break
    in_code = False
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            in_code = not in_code
        if in_code:
            continue
        for target in LINK.findall(line):
            if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                continue  # a web address, a mail address or an anchor on the same page
            path = target.split("#", 1)[0]
            resolved = (page.parent / path).resolve()
            # ../shared/... is the shared folder beside the repository: present on the
            # developers' machines and CI's, checked when it is there.
            outside = root.resolve() not in resolved.parents and resolved != root.resolve()
            if outside and not resolved.exists() and "shared" in pathlib.Path(path).parts:
                continue
            if not resolved.exists():
                found.append(f"line {number}: the link to '{target}' names no file")
    return found


def tick_conditions(root):
    """(bit, name) of every condition in the header's names table, through its enum's bits."""
    text = (root / CONDITIONS_HEADER).read_text(encoding="utf-8")
    bits = {name: int(bit) for name, bit in re.findall(r"^\s*(\w+) = 1u << (\d+),", text, re.M)}
    names = re.findall(r'\{TickCondition::(\w+), "(\w+)"\}', text)
    return [(bits.get(condition, -1), name) for condition, name in names]


def flags_table_defects(root):
    """The flags table of the trace format against the conditions the header defines."""
    lines = (root / FLAGS_PAGE).read_text(encoding="utf-8").splitlines()
    if FLAGS_TABLE_HEAD not in lines:
        return [f"no table headed '{FLAGS_TABLE_HEAD}' (the trace's flags)"]
    start = lines.index(FLAGS_TABLE_HEAD) + 2
    rows = []
    for line in lines[start:]:
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        rows.append((int(cells[0]), int(cells[1]), cells[2].strip("`")))
    documented = [(bit, name) for bit, value, name in rows if value == 1 << bit]
    if len(documented) != len(rows):
        return ["a row of the flags table whose value is not 2 to the power of its bit"]
    defined = tick_conditions(root)
    if documented != defined:
        return [f"the flags table lists {documented}, but {CONDITIONS_HEADER} defines {defined}"]
    return []


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    failures = 0
    pages = tracked_pages(root)
    for page in pages:
        for defect in defects(page, root):
            print(f"{page.relative_to(root)}: {defect}")
            failures += 1
    if (root / CONDITIONS_HEADER).exists():
        for defect in flags_table_defects(root):
            print(f"{FLAGS_PAGE}: {defect}")
            failures += 1
    print(f"check-docs: {len(pages)} pages, {failures} defects")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
