# Issue 13's cases that are refused on the command line (ctest -L reliability): numbers checked
# like files, runs and paths bounded in length, strict OBJ and path parsing, and the viewer
# without a display. Each gives status 2 and one line naming the option or file and the defect.
# Included from Apps/proxima/CMakeLists.txt, whose variables (defaultMesh, defaultPath, testData)
# it uses.
set(out ${CMAKE_CURRENT_BINARY_DIR}/reliability)
# Each test writes (or must not write) files of its own name: ctest -j runs them side by side.
set(runDefault run --mesh ${defaultMesh} --path ${defaultPath})

# Numbers: NaN, infinity, hexadecimal and absurd values are refused, in short numbers.
proxima_add_cli_test(run.radius-nan 2 RELIABILITY NO_FILE ${out}-run-radius-nan.csv
  ARGS ${runDefault} --out ${out}-run-radius-nan.csv --radius nan
  STDERR "--radius: not a finite decimal number: nan")
proxima_add_cli_test(path.radius-nan 2 RELIABILITY NO_FILE ${out}-path-radius-nan.csv
  ARGS path press-stroke --mesh ${defaultMesh} --radius nan --out ${out}-path-radius-nan.csv
  STDERR "--radius: not a finite decimal number: nan")
proxima_add_cli_test(run.scale-nan 2 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-scale-nan.csv --scale nan
  STDERR "--scale: not a finite decimal number: nan")
proxima_add_cli_test(run.stiffness-in-short-numbers 2 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-stiffness-in-short-numbers.csv --stiffness -1
  STDERR "--stiffness: must be above 0 and at most 1e\\+06 N/m, not -1")
proxima_add_cli_test(run.rate-absurd 2 RELIABILITY NO_FILE ${out}-run-rate-absurd.csv
  ARGS ${runDefault} --out ${out}-run-rate-absurd.csv --rate 1e9
  STDERR "--rate: must be from 10 to 100000 Hz, not 1e9")
proxima_add_cli_test(path.rate-absurd 2 RELIABILITY NO_FILE ${out}-path-rate-absurd.csv
  ARGS path press-stroke --mesh ${defaultMesh} --rate 1e9 --out ${out}-path-rate-absurd.csv
  STDERR "--rate: must be from 10 to 100000 Hz, not 1e9")
proxima_add_cli_test(run.max-force-hexadecimal 2 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-max-force-hexadecimal.csv --max-force 0x10
  STDERR "--max-force: not a finite decimal number: 0x10")
proxima_add_cli_test(run.dynamic-friction-above-static 2 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-dynamic-friction-above-static.csv --static-friction 0.3 --dynamic-friction 0.5
  STDERR "--dynamic-friction: mu_d 0.5 is above --static-friction mu_s 0.3: give mu_d <= mu_s")
proxima_add_cli_test(run.skin-not-below-radius 2 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-skin-not-below-radius.csv --skin 0.001
  STDERR "--skin: 0.001 m is not smaller than --radius 0.001 m")
proxima_add_cli_test(run.radius-larger-than-the-scene 2 RELIABILITY NO_FILE ${out}-run-radius-larger-than-the-scene.csv
  ARGS ${runDefault} --out ${out}-run-radius-larger-than-the-scene.csv --radius 0.5
  STDERR "^proxima: --radius: 0.5 m is larger than the whole scene \\(its bounding box's diagonal is 0.17[0-9]* m\\)")
proxima_add_cli_test(run.scene-scale-absurd 2 RELIABILITY
  ARGS run --scene ${testData}/huge-scale-scene.json --path ${defaultPath} --out ${out}-run-scene-scale-absurd.csv
  STDERR "huge-scale-scene.json: objects\\[0\\].scale: must be a number above 0 and at most 1e\\+06")
proxima_add_cli_test(run.scene-dynamic-friction-above-static 2 RELIABILITY
  ARGS run --scene ${testData}/dynamic-above-static-scene.json --path ${defaultPath} --out ${out}-run-scene-dynamic-friction-above-static.csv
  STDERR "dynamic-above-static-scene.json: objects\\[0\\].material.dynamic_friction: mu_d 0.5 is above static_friction mu_s 0.3")

# Length: a path row at t = 1e9 s is refused before a trace row is written, not run until the
# disk is full; --max-ticks moves the limit either way.
proxima_add_cli_test(run.path-far-in-time 2 RELIABILITY NO_FILE ${out}-run-path-far-in-time.csv
  ARGS run --mesh ${defaultMesh} --path ${testData}/far-future-path.csv --out ${out}-run-path-far-in-time.csv
  STDERR "^proxima: --max-ticks: [^\n]*far-future-path.csv \\(1e\\+09 s\\) is 1e\\+12 ticks at 1000 Hz, more than the limit of 1e\\+07 \\(give --max-ticks to go past it\\)")
proxima_add_cli_test(run.max-ticks-lowered 2 RELIABILITY NO_FILE ${out}-run-max-ticks-lowered.csv
  ARGS ${runDefault} --out ${out}-run-max-ticks-lowered.csv --max-ticks 100
  STDERR "^proxima: --max-ticks: [^\n]* ticks at 1000 Hz, more than the limit of 100 ")
proxima_add_cli_test(run.max-ticks-raised 0 RELIABILITY
  ARGS ${runDefault} --out ${out}-run-max-ticks-raised.csv --max-ticks 1e15
  STDOUT "\"ticks\": [1-9]")
proxima_add_cli_test(path.probe-too-long 2 RELIABILITY NO_FILE ${out}-path-probe-too-long.csv
  ARGS path probe --mesh ${defaultMesh} --duration 3600 --rate 100000 --out ${out}-path-probe-too-long.csv
  STDERR "^proxima: --max-ticks: --duration 3600 s is 3.6e\\+08 ticks at 100000 Hz, more than the limit of 1e\\+07")

# Strict parsing: what used to be read leniently or dropped in silence.
proxima_add_cli_test(run.hexadecimal-in-path 2 RELIABILITY NO_FILE ${out}-run-hexadecimal-in-path.csv
  ARGS run --mesh ${defaultMesh} --path ${testData}/hexadecimal-path.csv --out ${out}-run-hexadecimal-in-path.csv
  STDERR "hexadecimal-path.csv: line 2: z is not a number \\('0x10'\\)")
proxima_add_cli_test(run.obj-cut-off-mid-face 2 RELIABILITY NO_FILE ${out}-run-obj-cut-off-mid-face.csv
  ARGS run --mesh ${testData}/cut-off-face.obj --path ${defaultPath} --out ${out}-run-obj-cut-off-mid-face.csv
  STDERR "cut-off-face.obj: line 9: 'f' with 2 corners: it needs at least 3")

# The viewer: no display is one line, before any window; a screenshot of a scripted path comes
# from the lockstep state at --at, not from living through --at seconds; --at past the path's
# end is refused.
find_program(PROXIMA_ENV env)
proxima_add_cli_test(view.no-display 2 RELIABILITY NO_FILE ${out}-view-no-display.png
  LAUNCHER ${PROXIMA_ENV} -u DISPLAY
  ARGS view --mesh ${defaultMesh} --path ${defaultPath} --screenshot ${out}-view-no-display.png
  STDERR "^proxima: proxima view: DISPLAY is not set, so there is no display to draw on: run it under a virtual one, as in xvfb-run -a proxima view")
proxima_add_cli_test(view.display-that-does-not-open 2 RELIABILITY NO_FILE ${out}-view-display-that-does-not-open.png
  LAUNCHER ${PROXIMA_ENV} DISPLAY=:9999
  ARGS view --mesh ${defaultMesh} --path ${defaultPath} --screenshot ${out}-view-display-that-does-not-open.png
  STDERR "^proxima: proxima view: cannot open the display DISPLAY=:9999")
proxima_add_cli_test(view.at-after-the-path 2 RELIABILITY
  ARGS view --mesh ${defaultMesh} --path ${defaultPath} --screenshot ${out}-view-at-after-the-path.png --at 100
  STDERR "^proxima: --at: 100 s is after the end of the path \\(")
find_program(PROXIMA_XVFB_FOR_CLI Xvfb)
if(PROXIMA_XVFB_FOR_CLI)
  proxima_add_cli_test(view.screenshot-from-lockstep 0 RELIABILITY
    LAUNCHER ${PROJECT_SOURCE_DIR}/Library/VTK/Testing/run-under-xvfb.sh
    ARGS view --mesh ${defaultMesh} --path ${defaultPath} --screenshot ${out}-view-screenshot-from-lockstep.png --at 0.9
    STDOUT "screenshot-from-lockstep.png: 800x600 at t = 0.9000 s \\(lockstep\\), [0-9]+ contacts")
  if(PROXIMA_ENABLE_SANITIZERS)
    # Mesa's software driver leaks blocks LeakSanitizer cannot name (as for VTK.ImageTests).
    set_tests_properties(proxima.view.screenshot-from-lockstep
      PROPERTIES ENVIRONMENT "ASAN_OPTIONS=detect_leaks=0")
  endif()
endif()
