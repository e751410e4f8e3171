#!/usr/bin/python3
"""Tools.ci-time-table: Tools/ci-time.sh's step table read from logs of .ci/run.

- .ci/run itself, run in a scratch copy whose steps are stand-ins (the same names, each doing
  nothing), writes a log whose step lines and last line ("ci: total N s") the table reads: every
  step in order and the total, and --table exits 0;
- the same with a step that fails: the total line says so, the table stops at the failed step
  and --table exits 1;
- a log with step times of the size a warm CI run takes (the numbers below) gives those numbers, minutes and
  the total; a log cut off before its total line exits 1 and says the run did not end normally.

Usage: test_ci_time_table.py SOURCE_DIR
"""
import os
import shutil
import stat
import subprocess
import sys
import tempfile

source = sys.argv[1]
table_tool = os.path.join(source, "Tools", "ci-time.sh")
work = tempfile.mkdtemp(prefix="proxima-ci-time-table-")

STEPS = ["bash Tools/quickstart.sh",
         "ctest --test-dir build --output-on-failure -j2 --output-junit ctest-results.xml",
         "/usr/bin/python3 Tools/check-skipped-tests.py build build/ctest-results.xml",
         "/usr/bin/python3 Tools/check-docs.py .",
         "/usr/bin/python3 Tools/check-includes.py .",
         "bash Tools/check-format.sh",
         "bash Tools/sanitizer-tests.sh",
         "bash Tools/thread-sanitizer-tests.sh",
         "bash Tools/fuzz-smoke.sh"]


def fail(message):
    sys.exit(f"ci-time table test: {message}")


def table(log):
    done = subprocess.run(["bash", table_tool, "--table", log], capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


def rows(output):
    """The step rows of a table: (step, seconds) in order."""
    found = []
    for line in output.splitlines():
        if line.startswith("| `"):
            cells = [cell.strip() for cell in line.strip("|").split("|")]
            found.append((cells[0].strip("`"), int(cells[1])))
    return found


def run_ci(failing_script=None):
    """.ci/run in a scratch checkout whose tools are stand-ins; returns its log's path."""
    checkout = os.path.join(work, "checkout")
    shutil.rmtree(checkout, ignore_errors=True)
    os.makedirs(os.path.join(checkout, ".ci"))
    os.makedirs(os.path.join(checkout, "Tools"))
    os.makedirs(os.path.join(checkout, "bin"))
    shutil.copy(os.path.join(source, ".ci", "run"), os.path.join(checkout, ".ci", "run"))
    for name in ["quickstart.sh", "check-format.sh", "sanitizer-tests.sh",
                 "thread-sanitizer-tests.sh", "fuzz-smoke.sh"]:
        with open(os.path.join(checkout, "Tools", name), "w") as out:
            out.write(f"echo 'stand-in for {name}'\n")
            if name == failing_script:
                out.write("exit 3\n")
    for name in ["check-skipped-tests.py", "check-docs.py", "check-includes.py"]:
        with open(os.path.join(checkout, "Tools", name), "w") as out:
            out.write(f"print('stand-in for {name}')\n")
    ctest = os.path.join(checkout, "bin", "ctest")
    with open(ctest, "w") as out:
        # A test's output may itself hold step-like words; only .ci/run's own lines count.
        out.write("#!/bin/sh\necho \"100% tests passed: ci: 'nothing' took 99 s, not a step\"\n")
    os.chmod(ctest, os.stat(ctest).st_mode | stat.S_IXUSR)
    log = os.path.join(work, "ci.log")
    environment = dict(os.environ, PATH=os.path.join(checkout, "bin") + ":" + os.environ["PATH"])
    with open(log, "w") as out:
        subprocess.run(["bash", os.path.join(checkout, ".ci", "run")], stdout=out,
                       stderr=subprocess.STDOUT, env=environment, stdin=subprocess.DEVNULL)
    return log


# The real .ci/run, every step passing.
log = run_ci()
with open(log) as f:
    lines = f.read().splitlines()
if not lines or not lines[-1].startswith("ci: total ") or "failed" in lines[-1]:
    fail(f".ci/run's last line is not its total: {lines[-1:]}")
status, output = table(log)
if status != 0 or [step for step, _ in rows(output)] != STEPS or "**total**" not in output:
    fail(f"a whole passing run: status {status}, table:\n{output}")

# The real .ci/run with the format check failing: the steps before it, and a failed total.
log = run_ci(failing_script="check-format.sh")
with open(log) as f:
    last = f.read().splitlines()[-1]
if not (last.startswith("ci: total ") and last.endswith(" s (failed, status 3)")):
    fail(f"a failed run's last line: {last!r}")
status, output = table(log)
if status != 1 or [step for step, _ in rows(output)] != STEPS[:5] or "The run failed" not in output:
    fail(f"a run whose format check failed: status {status}, table:\n{output}")

# Step times of the size a warm CI run takes, as .ci/run prints them, with other output between.
measured = [249, 355, 2, 4, 1, 7, 302, 39, 40]
saved = []
elapsed = 0
for step, seconds in zip(STEPS, measured):
    elapsed += seconds
    saved += [f"output of {step.split()[0]}", f"ci: '{step}' took {seconds} s ({elapsed} s in all)"]
whole = os.path.join(work, "measured.log")
with open(whole, "w") as out:
    out.write("\n".join(saved + [f"ci: total {elapsed} s"]) + "\n")
status, output = table(whole)
if status != 0 or rows(output) != list(zip(STEPS, measured)):
    fail(f"the measured run's steps: status {status}, table:\n{output}")
if "| **total** | **999** | **16:39** |" not in output or "Under the goal" not in output:
    fail(f"the measured run's total (999 s, 16:39): table:\n{output}")
if "| 5:55 |" not in output:
    fail(f"355 s is 5:55: table:\n{output}")

# Cut off before the total line: the last step's running count, and a failure.
cut = os.path.join(work, "cut.log")
with open(cut, "w") as out:
    out.write("\n".join(saved[:6]) + "\n")
status, output = table(cut)
if status != 1 or "did not end normally" not in output or "| 606 |" not in output:
    fail(f"a log without its total line: status {status}, table:\n{output}")

shutil.rmtree(work)
print("ci-time table: a passing and a failing .ci/run, a measured log and a cut-off one read right")
