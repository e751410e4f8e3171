#!/usr/bin/env python3
"""Every number option's range, as --help shows it, is the range its checks take: for each
program and command below, each option whose help gives a range ("above 0 and at most 1 m",
"from 10 to 100000 Hz", "a whole number from 64 to 8192 pixels") is given a value just outside
it, which must be refused in one line naming the option and that same range (status 2), and the
range's own ends (or its middle, for an end left out), which nothing may refuse by naming the
option. An option of several numbers ("FLOAT:... x 3") is given the value in each place. The command
lines name a file that does not exist, or one that cannot be written, so that nothing runs once
the options are taken. A range shown in CLI11's own words ("in [1 - 1024]") is a failure: its
check is not the table's (IO/InputChecks/ParameterRanges.h), and its message not the others'.

Usage: check_help_ranges.py BIN_DIR SOURCE_DIR
"""
import os
import re
import subprocess
import sys

OPTION = re.compile(r"^(--[\w-]+) (?:FLOAT|INT|UINT|NUMBER)[^:\s]*:(.+?)(?:=\S+)?"
                    r"(?: x (\d+))?(?: (?:Excludes|Needs): .*)?$")
NUMBER = r"(-?[0-9.]+(?:e[+-]?[0-9]+)?)"
FORMS = [
    (re.compile(rf"^(a whole number )?above {NUMBER} and at most {NUMBER}\b"), True, True),
    (re.compile(rf"^(a whole number )?from {NUMBER} to {NUMBER}\b"), False, True),
    (re.compile(rf"^(a whole number )?above {NUMBER}\b"), True, False),
    (re.compile(rf"^(a whole number )?from {NUMBER}\b"), False, False),
]
# The rules between options that the ends of a range meet: --skin smaller than --radius.
PARTNERS = {"--skin": ["--radius", "1"]}
CLI11_RANGE = re.compile(r"\bin \[[^\]]* - [^\]]*\]")


class Range:
    def __init__(self, option, count, words, whole, low, excluded, high):
        self.option = option
        self.count = count  # numbers the option takes at once
        self.words = words  # as --help shows them: "a whole number from 1 to 1024"
        self.whole = whole
        self.low = low
        self.excluded = excluded
        self.high = high  # None: no upper end


def ranges(help_text):
    """(every option with a range, the options whose range is in CLI11's own words)."""
    found, cli11 = [], []
    for line in help_text.splitlines():
        # The option's column ends where two spaces begin its description.
        column = line.strip().split("  ")[0]
        match = OPTION.match(column)
        if not match:
            if column.startswith("--") and CLI11_RANGE.search(column):
                cli11.append(column)
            continue
        option, words, count = match.group(1), match.group(2).strip(), int(match.group(3) or 1)
        if CLI11_RANGE.search(words):
            cli11.append(column)
            continue
        for form, excluded, bounded in FORMS:
            m = form.match(words)
            if m:
                high = float(m.group(3)) if bounded else None
                found.append(Range(option, count, m.group(0), m.group(1) is not None,
                                   float(m.group(2)), excluded, high))
                break
    return found, cli11


def text(value, whole):
    return str(int(value)) if whole else repr(float(value))


def values(whole, low, excluded, high):
    """(values outside, values inside)."""
    step = 1.0 if whole else max(abs(low), abs(high or 0.0), 1.0) * 1e-6
    outside = [low if excluded else low - (1.0 if whole else max(abs(low) * 1e-6, 1e-9))]
    inside = []
    if not excluded:
        inside.append(low)
    elif high is not None:
        inside.append(low + (high - low) / 2 if not whole else low + 1)
    if high is not None:
        outside.append(high + (1.0 if whole else max(abs(high) * 1e-6, step * 1e-3)))
        inside.append(high)
    return outside, inside


def main():
    bin_dir, source = sys.argv[1:3]
    missing = os.path.join(bin_dir, "no-such-file.csv")
    mesh = os.path.join(source, "Data", "Meshes", "icosphere-4.obj")
    out = os.path.join(bin_dir, "help-ranges-out")
    proxima = os.path.join(bin_dir, "proxima")
    # A mesh format generate cannot write: refused before any shape is made.
    unwritable = out + ".txt"
    programs = [
        ("proxima-inspector", [os.path.join(bin_dir, "proxima-inspector")],
         ["--mesh", mesh, "--path", missing, "--report", out + ".json"]),
        ("proxima-trainer", [os.path.join(bin_dir, "proxima-trainer")],
         ["--exercise", missing, "--path", missing, "--report", out + ".json"]),
        ("proxima", [proxima, "run"], ["--mesh", mesh, "--path", missing, "--out", out + ".csv"]),
        ("proxima", [proxima, "view"],
         ["--mesh", mesh, "--path", missing, "--screenshot", out + ".png"]),
        ("proxima", [proxima, "path", "press-stroke"], ["--mesh", missing, "--out", out + ".csv"]),
        ("proxima", [proxima, "tree"], ["--mesh", missing]),
        ("proxima", [proxima, "generate", "icosphere"], ["--out", unwritable]),
        ("proxima", [proxima, "generate", "box"], ["--out", unwritable]),
        ("proxima", [proxima, "generate", "grid"], ["--out", unwritable]),
        ("proxima", [proxima, "generate", "prism"], ["--out", unwritable]),
        ("proxima", [proxima, "inspect"], ["--mesh", missing, "--report", out + ".json"]),
        ("proxima", [proxima, "serve"], ["--listen", "127.0.0.1:99999"]),
    ]
    failures = []
    checked = 0
    for name, command, base in programs:
        shown = subprocess.run(command + ["--help"], capture_output=True, text=True, timeout=60)
        assert shown.returncode == 0, (command, shown.stderr)
        found, cli11 = ranges(shown.stdout)
        assert found, (command, "no ranges in --help", shown.stdout)
        program = ' '.join(command[1:]) or name
        for column in cli11:
            failures.append(f"{program} --help: {column!r} shows CLI11's range, not the table's")
        for r in found:
            option = r.option
            outside, inside = values(r.whole, r.low, r.excluded, r.high)
            for value in outside + inside:
                given = text(value, r.whole)
                result = subprocess.run(command + base + PARTNERS.get(option, []) +
                                        [option] + [given] * r.count, capture_output=True,
                                        text=True, timeout=60)
                checked += 1
                lines = result.stderr.splitlines()
                named = [line for line in lines if line.startswith(f"{name}: {option}:")]
                what = f"{program} {option} {given}"
                if value in outside:
                    # The shared words: the same range as --help, and the value given.
                    expected = f"{name}: {option}: must be {r.words}"
                    if (result.returncode != 2 or len(lines) != 1 or not named or
                            not named[0].startswith(expected)):
                        failures.append(f"{what}: outside the help's range, but status "
                                        f"{result.returncode}, stderr {result.stderr!r}, not "
                                        f"{expected!r}")
                elif named:
                    failures.append(f"{what}: inside the help's range, but {named[0]!r}")
    print(f"{checked} command lines checked")
    for failure in failures:
        print(failure)
    assert not failures, f"{len(failures)} failures"


if __name__ == "__main__":
    main()
