#!/usr/bin/env python3
"""Runs every example of the documentation that is marked runnable, as written, and fails with
the page, the line and the output of each one that fails.

A block is runnable when the line just before its fence is the marker `<!-- runnable -->` and
the fence opens a ```sh or ```python block. It runs in a fresh temporary folder laid out like a
checkout after the quick start: the repository's top-level entries linked in (Data/, Apps/, ...),
and build/ a folder of its own holding links to the build's entries (bin/, lib/, Data/, ...), so
that the files a block writes, in its current folder or in build/, land in the temporary folder
and never in the tree. An sh block runs in bash with -e, so that every command of it must
succeed; a python block is saved as example.py and run by /usr/bin/python3 with the build's
package on PYTHONPATH, as Documentation/Python.md tells a reader to run it. A marker before any
other line, or a page with markers but no runnable block, is a failure too, so that a mistyped
marker is not a block silently left out.

Usage: run_doc_examples.py SOURCE_DIR BINARY_DIR [PAGE...]
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = "<!-- runnable -->"
FENCE = re.compile(r"^(\s*)```(\w*)\s*$")
RUNNABLE_LANGUAGES = ("sh", "python")
# An example of the docs is a few seconds of work; a minute is a hang.
TIMEOUT_SECONDS = 60
# Output kept in a failure's report.
REPORT_CHARACTERS = 4000


class Block:
    def __init__(self, page, line, language, text):
        self.page = page
        self.line = line
        self.language = language
        self.text = text

    def where(self, root):
        return f"{os.path.relpath(self.page, root)}:{self.line}"


def runnable_blocks(page):
    """The blocks of `page` marked runnable, and the marker misuses found on it."""
    lines = page.read_text(encoding="utf-8").splitlines()
    blocks, misuses = [], []
    index = 0
    while index < len(lines):
        if lines[index].strip() != MARKER:
            index += 1
            continue
        marker_line = index + 1
        fence = FENCE.match(lines[index + 1]) if index + 1 < len(lines) else None
        if not fence or fence.group(2) not in RUNNABLE_LANGUAGES:
            misuses.append((marker_line, "the runnable marker is not followed by a ```sh or "
                                         "```python fence"))
            index += 1
            continue
        indent, language = fence.group(1), fence.group(2)
        body = []
        end = index + 2
        while end < len(lines) and not lines[end].strip().startswith("```"):
            # A block inside a list item is indented with its fence.
            body.append(lines[end][len(indent):] if lines[end].startswith(indent) else lines[end])
            end += 1
        if end == len(lines):
            misuses.append((marker_line, "the runnable block is never closed"))
            break
        blocks.append(Block(page, index + 2, language, "\n".join(body) + "\n"))
        index = end + 1
    return blocks, misuses


def checkout_like_folder(source, binary):
    """A temporary folder with the repository's entries linked in, and build/ of its own."""
    folder = pathlib.Path(tempfile.mkdtemp(prefix="proxima-doc-example-"))
    resolved_binary = binary.resolve()
    for entry in source.iterdir():
        if entry.name in (".git", "build") or entry.resolve() == resolved_binary:
            continue
        (folder / entry.name).symlink_to(entry.resolve())
    build = folder / "build"
    build.mkdir()
    for entry in binary.iterdir():
        (build / entry.name).symlink_to(entry.resolve())
    return folder


def run_block(block, source, binary):
    """(failure report or None, seconds)."""
    folder = checkout_like_folder(source, binary)
    environment = dict(os.environ)
    try:
        if block.language == "sh":
            command = ["bash", "-e", "-o", "pipefail", "-c", block.text]
        else:
            script = folder / "example.py"
            script.write_text(block.text, encoding="utf-8")
            command = ["/usr/bin/python3", str(script)]
            package = str(folder / "build" / "lib" / "python3" / "dist-packages")
            environment["PYTHONPATH"] = os.pathsep.join(
                [package] + [p for p in [environment.get("PYTHONPATH")] if p])
        start = time.monotonic()
        try:
            result = subprocess.run(command, cwd=folder, env=environment, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                    timeout=TIMEOUT_SECONDS)
        except subprocess.TimeoutExpired as expired:
            output = expired.stdout or ""
            if isinstance(output, bytes):
                output = output.decode(errors="replace")
            return (f"{block.where(source)}: the {block.language} block did not finish in "
                    f"{TIMEOUT_SECONDS} s\n{output[-REPORT_CHARACTERS:]}",
                    time.monotonic() - start)
        seconds = time.monotonic() - start
        if result.returncode != 0:
            return (f"{block.where(source)}: the {block.language} block failed with status "
                    f"{result.returncode}\n{block.text}--- its output:\n"
                    f"{result.stdout[-REPORT_CHARACTERS:]}", seconds)
        return None, seconds
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def documentation_pages(source):
    return [source / "README.md"] + sorted((source / "Documentation").glob("*.md"))


def main():
    source, binary = (pathlib.Path(argument).resolve() for argument in sys.argv[1:3])
    pages = ([pathlib.Path(page).resolve() for page in sys.argv[3:]] or
             documentation_pages(source))
    failures = []
    ran = 0
    for page in pages:
        blocks, misuses = runnable_blocks(page)
        for line, problem in misuses:
            failures.append(f"{os.path.relpath(page, source)}:{line}: {problem}")
        for block in blocks:
            failure, seconds = run_block(block, source, binary)
            ran += 1
            print(f"{block.where(source)}: {block.language}, {seconds:.1f} s, "
                  f"{'failed' if failure else 'passed'}", flush=True)
            if failure:
                failures.append(failure)
    print(f"{ran} runnable blocks run, {len(failures)} failures")
    for failure in failures:
        print(failure)
    if ran == 0:
        print("no block is marked runnable: the marker is " + MARKER)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
