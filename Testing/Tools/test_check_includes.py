#!/usr/bin/python3
"""Tools.check-includes: Tools/check-includes.py, the layer table of Documentation/Architecture.md
as a rule. The project's own tree passes. In a copy of the tree's layout with the real table, an
include the table forbids fails naming the file, line and layers: the kernel reaching up into
Runtime, a Geometry header including Proxy, and the VTK layer including an IO layer in a
header (its `.cpp` files may). Includes the table allows, a test file's includes and a file's
own layer pass. A layer the table has no row for fails too.

Usage: test_check_includes.py SOURCE_DIR
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

source = pathlib.Path(sys.argv[1])
checker = source / "Tools" / "check-includes.py"


def fail(message):
    sys.exit(f"check-includes test: {message}")


def run(root):
    done = subprocess.run(["/usr/bin/python3", str(checker), str(root)], capture_output=True,
                          text=True, check=False)
    return done.returncode, done.stdout + done.stderr


status, output = run(source)
if status != 0:
    fail(f"the project's tree should pass, it gave {status}:\n{output}")

work = pathlib.Path(tempfile.mkdtemp(prefix="proxima-check-includes-"))
try:
    (work / "Documentation").mkdir()
    shutil.copy(source / "Documentation" / "Architecture.md", work / "Documentation")
    # Every layer of the real tree, empty, so that the table's rows all have their folder.
    for folder in (source / "Library").iterdir():
        if folder.is_dir():
            (work / "Library" / folder.name).mkdir(parents=True)
    for folder in (source / "Library" / "IO").iterdir():
        if folder.is_dir():
            (work / "Library" / "IO" / folder.name).mkdir(parents=True, exist_ok=True)

    def plant(relative, *includes):
        path = work / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text("".join(f'#include "{name}"\n' for name in includes) + "int x;\n")

    plant("Library/Proxy/Allowed.h", "Geometry/SphereTree.h", "Core/Vec3.h", "Proxy/Other.h")
    plant("Library/VTK/AllowedSource.cpp", "IO/Scene/SceneFile.h", "Runtime/HapticState.h")
    plant("Library/Proxy/Testing/TestAnything.cxx", "IO/Scene/SceneFile.h")
    status, output = run(work)
    if status != 0:
        fail(f"allowed includes should pass, it gave {status}:\n{output}")

    plant("Library/Proxy/Reaching.cpp", "Runtime/HapticState.h")
    plant("Library/Geometry/Upward.h", "Core/Vec3.h", "Proxy/ProxySolver.h")
    plant("Library/VTK/vtkSomething.h", "IO/Scene/SceneFile.h")
    status, output = run(work)
    expected = [
        "Library/Proxy/Reaching.cpp:1: Proxy may not include Runtime",
        "Library/Geometry/Upward.h:2: Geometry may not include Proxy",
        "Library/VTK/vtkSomething.h:1: VTK includes IO/Scene in a header",
        "3 forbidden includes",
    ]
    if status != 1 or any(line not in output for line in expected):
        fail(f"three planted includes should fail, named; got {status}:\n{output}")

    (work / "Library" / "Planted").mkdir()
    status, output = run(work)
    if status != 1 or "the table has no row for Planted" not in output:
        fail(f"a layer without a row should fail; got {status}:\n{output}")
finally:
    shutil.rmtree(work)
print("check-includes test: the tree passes, planted forbidden includes fail, named")
