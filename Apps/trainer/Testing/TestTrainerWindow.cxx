// The trainer's window under Xvfb (QTest), on the shipped liver exercises:
//   - it opens on an exercise and shows the scene with the targets framed, compared with a
//     baseline image as the VTK image tests are;
//   - the mouse, moved over the liver by Qt mouse events and pressed in with wheel events, makes
//     contact that the HUD reports, and M marks the spot touched;
//   - a finger path recorded as a device session and replayed through the threaded runtime is
//     scored live, every tick, to the same result as the headless session of the same path (the
//     independent run: lockstep on a virtual clock);
//   - a session recorded in the window replays; a device that is not there is named and the
//     mouse stays.
// Nothing here asserts on speed: waits have generous deadlines and end as soon as the state is
// reached.
#include "Exercises/ExerciseFile.h"
#include "Exercises/HeadlessSession.h"
#include "TrainerWindow.h"
#include "Window/TrainerWindowMain.h"

#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/Scene/SceneTissue.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Exercises/ExerciseScene.h"
#include "ImageComparison.h"
#include "WindowTesting.h"
#include "VTK/vtkHapticMouseFinger.h"

#include <QAction>
#include <QApplication>
#include <QMessageBox>
#include <QSurfaceFormat>
#include <QTest>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>
#include <QWheelEvent>

#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

namespace
{
using namespace proxima;
using namespace proxima::trainer;
using proxima::shell::testing::waitUntil;
using proxima::shell::testing::writePathAsRecording;

const std::string kExercises = PROXIMA_EXERCISES;
const std::string kPaths = PROXIMA_SOURCE_DIR "/Data/Paths/Trainer";
const std::string kOutput = PROXIMA_TEST_OUTPUT;

// The trainer's window keeping every tick it scored, so that a test can score them again.
class TickKeepingTrainerWindow : public TrainerWindow
{
public:
  using TrainerWindow::TrainerWindow;
  const std::vector<HapticState>& ticksScored() const { return m_ticksScored; }

protected:
  void ticksArrived(const std::vector<HapticState>& ticks) override
  {
    m_ticksScored.insert(m_ticksScored.end(), ticks.begin(), ticks.end());
    TrainerWindow::ticksArrived(ticks);
  }
  void sessionRestarted() override
  {
    m_ticksScored.clear();
    TrainerWindow::sessionRestarted();
  }

private:
  std::vector<HapticState> m_ticksScored;
};

// The live ticks a starved machine disturbed: the proxy loop stopped at its budget, the servo
// skipped ticks or faded a stale proxy's force. Seconds of them between `from` and `to`.
double disturbedSeconds(const std::vector<HapticState>& ticks, double from, double to,
                        double period)
{
  double seconds = 0.0;
  for (std::size_t i = 0; i < ticks.size(); ++i)
  {
    const HapticState& tick = ticks[i];
    if (tick.time < from || tick.time > to)
    {
      continue;
    }
    const double skipped =
      i > 0 ? static_cast<double>(tick.tick - ticks[i - 1].tick - 1) * period : 0.0;
    seconds += skipped;
    // A tissue's surface still a step late at the second update after the step's tick (its
    // solid's thread held off) is disturbed too. The first update often is: the kidney's step
    // takes about a tick, so 4 % of the updates meet the surface before it on an idle machine.
    const bool lagging = tick.conditions.has(TickCondition::surfaceLagging) && i > 0 &&
                         ticks[i - 1].conditions.has(TickCondition::surfaceLagging);
    if (tick.conditions.hasAny(TickCondition::budgetLimited | TickCondition::forceFading) ||
        lagging || tick.proxyStale)
    {
      seconds += period;
    }
  }
  return seconds;
}

// A window on the shipped exercise `name`, shown; a soft organ's exercise with its tissue, which
// `tissue` (when given) receives too.
template <typename Window = TrainerWindow>
std::unique_ptr<Window> openExercise(const std::string& name, const std::string& device,
                                     int width = 800, int height = 600,
                                     std::shared_ptr<TissueDynamics>* tissue = nullptr)
{
  const Exercise exercise = readExerciseFile(kExercises + "/" + name + ".json");
  LoadedScene loaded = loadExerciseScene(exerciseRunSettings(exercise, ""));
  shell::HapticWindowSettings settings;
  settings.tissue = buildSceneTissue(loaded, exercise.stiffness, exercise.rate);
  if (tissue != nullptr)
  {
    *tissue = settings.tissue;
  }
  settings.title = exercise.name;
  settings.scene = std::move(loaded.scene);
  settings.radius = exercise.radius;
  settings.stiffness = exercise.stiffness;
  settings.maxForce = exercise.maxForce;
  settings.servoRate = exercise.rate;
  settings.device = device;
  settings.width = width;
  settings.height = height;
  auto window = std::make_unique<Window>(exercise, settings);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get()))
  {
    return nullptr;
  }
  return window;
}

void wheel(QWidget* widget, const QPoint& at, int notches)
{
  for (int i = 0; i < std::abs(notches); ++i)
  {
    QWheelEvent event(QPointF(at), QPointF(widget->mapToGlobal(at)), QPoint(),
                      QPoint(0, notches > 0 ? 120 : -120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(widget, &event);
    QTest::qWait(30);
  }
}

// The outcome a live replay must share with the headless session: passed, each task's targets
// touched, the damage events.
bool sameOutcome(const ExerciseScore& live, const ExerciseScore& headless)
{
  if (live.passed != headless.passed || live.damage.size() != headless.damage.size() ||
      live.tasks.size() != headless.tasks.size())
  {
    return false;
  }
  for (std::size_t t = 0; t < live.tasks.size(); ++t)
  {
    if (live.tasks[t].targets.touched != headless.tasks[t].targets.touched)
    {
      return false;
    }
  }
  return true;
}

// Replays `recording` (the path `path` as a device session) in `window` until its live outcome
// is the headless one's, and returns the attempt's score with `ticksScored` its ticks; false with
// `why` when it differs. A starved machine can change the outcome (a force out of a target's
// band for one disturbed tick starts its hold again, and the path may end before the hold does),
// so a replay whose outcome differs is made again only when its ticks were disturbed (skipped,
// budget-limited or stale), up to four times; an undisturbed one that differs fails at once.
// `onFrame` is called while each replay runs (to picture a moment of it).
bool replayUntilHeadlessOutcome(TickKeepingTrainerWindow& window, const std::string& recording,
                                const FingerPath& path, const ExerciseScore& headless,
                                const std::function<void()>& onFrame, ExerciseScore& live,
                                std::vector<HapticState>& ticksScored, std::string& why)
{
  const double period = 1.0 / window.exercise().rate;
  for (int attempt = 1;; ++attempt)
  {
    std::string error;
    if (!window.useDevice("replay:" + recording, error))
    {
      why = error;
      return false;
    }
    if (!waitUntil(
          [&] {
            onFrame();
            return window.latestState().time > path.endTime() + 0.3;
          },
          path.endTime() * 6.0 + 30.0))
    {
      why = "the replay did not reach the path's end";
      return false;
    }
    QTest::qWait(100);
    // The score and the ticks it counted, taken together (ticks arrive only in the event loop).
    live = window.score();
    ticksScored = window.ticksScored();
    if (sameOutcome(live, headless))
    {
      return true;
    }
    const double disturbed = disturbedSeconds(ticksScored, 0.0, path.endTime() + 0.3, period);
    why = "attempt " + std::to_string(attempt) + ": live " + (live.passed ? "passed" : "failed") +
          " with " + std::to_string(live.tasks[0].targets.touched) + " targets and " +
          std::to_string(live.damage.size()) + " damage events, headless " +
          std::to_string(headless.tasks[0].targets.touched) + " and " +
          std::to_string(headless.damage.size()) + "; " + std::to_string(disturbed) +
          " s of live ticks disturbed";
    if (!(disturbed > 0.0 && attempt < 4))
    {
      return false;
    }
    qInfo("%s: replaying again", why.c_str());
  }
}

// With PROXIMA_TRAINER_FIGURES=FOLDER the window is also saved, menus and all, as FOLDER/NAME:
// the pictures of Documentation/SurgicalTrainer.md come from these runs.
void saveFigure(QWidget* window, const char* name)
{
  proxima::shell::testing::saveFigure(window, "PROXIMA_TRAINER_FIGURES", name);
}
} // namespace

class TrainerWindowTest : public QObject
{
  Q_OBJECT

private slots:
  void opensOnTheExerciseWithItsTargetsFramed()
  {
    auto window = openExercise("liver-targets", "mouse");
    QVERIFY(window != nullptr);
    // A few frames: the loops are running, the finger rests above the liver, nothing touches.
    QVERIFY(waitUntil([&] { return window->ticksSeen() > 50; }, 30.0));
    QVERIFY2(window->hudText().find("Liver targets: touch A, B and C in order") !=
                 std::string::npos &&
               window->hudText().find("targets: 0 of 3 touched, next A") != std::string::npos,
             window->hudText().c_str());
    QCOMPARE(window->latestState().numContacts, 0);
    // The scene, the proxy and the exercise's targets framed, without the HUD and the plot,
    // whose times and servo figures differ from run to run (View > Show the HUD, H).
    auto* overlays = window->findChild<QAction*>("showOverlays");
    QVERIFY(overlays != nullptr);
    overlays->setChecked(false);
    const proxima::vtk::testing::ImageComparison image = proxima::vtk::testing::compareWithBaseline(
      window->view()->renderWindow(), "trainer-window-targets",
      PROXIMA_SOURCE_DIR "/Apps/trainer/Testing/Baselines", kOutput);
    QVERIFY2(image.matches, image.message.c_str());
  }

  void theMouseOverTheLiverPressesInAndMarksTheSpot()
  {
    auto window = openExercise("liver-palpation", "mouse");
    QVERIFY(window != nullptr);
    QWidget* view = window->view();
    const QPoint centre(view->width() / 2, view->height() / 2);
    QTest::mouseMove(view, centre);
    QVERIFY2(waitUntil([&] { return window->mouseFinger()->IsHovering(); }, 10.0),
             "the cursor over the liver's middle should find its surface");
    QCOMPARE(window->latestState().numContacts, 0);
    // Four notches press two radii (half a radius each): the proxy stays on the liver, the
    // finger goes in, and the HUD names what is touched.
    wheel(view, centre, 4);
    QVERIFY2(std::abs(window->mouseFinger()->GetDepth() - 2.0 * window->exercise().radius) < 1e-12,
             std::to_string(window->mouseFinger()->GetDepth()).c_str());
    // The proxy touches first and the force grows as the finger (at most 0.5 m/s) reaches its
    // depth: waited for, as a trainee waits for the press to be felt.
    QVERIFY2(waitUntil(
               [&] {
                 const HapticState state = window->latestState();
                 return state.numContacts > 0 && norm(state.force) > 0.1;
               },
               20.0),
             window->hudText().c_str());
    QVERIFY2(
      waitUntil([&] { return window->hudText().find("touching liver") != std::string::npos; }, 5.0),
      window->hudText().c_str());
    QVERIFY(norm(window->latestState().force) <= window->exercise().maxForce + 1e-9);
    // Session > Mark the spot touched, whose key is M. (Xvfb has no window manager to make the
    // window active, which Qt's shortcuts need: the action is triggered as the menu does.)
    auto* markAction = window->findChild<QAction*>("markSpot");
    QVERIFY(markAction != nullptr);
    QCOMPARE(markAction->shortcut(), QKeySequence(Qt::Key_M));
    markAction->trigger();
    QTest::qWait(100);
    saveFigure(window.get(), "trainer-window-palpation.png");
    const ExerciseScore score = window->score();
    QCOMPARE(score.tasks.size(), std::size_t{1});
    QCOMPARE(score.tasks[0].palpation.marks, 1);
    QVERIFY(score.tasks[0].palpation.mark.has_value());
    // The mark is the contact point: on the liver's surface under the proxy, a radius away.
    const double fromProxy = norm(*score.tasks[0].palpation.mark - window->latestState().proxy);
    QVERIFY2(std::abs(fromProxy - window->exercise().radius) < 1e-3,
             std::to_string(fromProxy).c_str());
    QCOMPARE(window->ticksDropped(), std::uint64_t{0});
  }

  void aReplayedPathIsScoredLiveAsTheHeadlessSessionScoresIt()
  {
    auto window = openExercise<TickKeepingTrainerWindow>("liver-targets", "mouse");
    QVERIFY(window != nullptr);
    const Exercise& exercise = window->exercise();
    const double period = 1.0 / exercise.rate;
    const std::string recording = kOutput + "/liver-targets-pass.recording.csv";
    const FingerPath path = readFingerPathFile(kPaths + "/liver-targets-pass.csv");
    std::string error;
    QVERIFY2(writePathAsRecording(path, exercise.rate, recording, error), error.c_str());
    const ExerciseScore headless =
      playHeadlessSession(exercise, path, "liver-targets-pass.csv", {});
    QVERIFY(headless.passed);
    bool pictured = false;
    ExerciseScore live;
    std::vector<HapticState> ticksScored;
    std::string why;
    const auto pictureBothTouched = [&] {
      if (!pictured && window->score().tasks[0].targets.touched == 2)
      {
        saveFigure(window.get(), "trainer-window-targets.png");
        pictured = true;
      }
    };
    QVERIFY2(replayUntilHeadlessOutcome(*window, recording, path, headless, pictureBothTouched,
                                        live, ticksScored, why),
             why.c_str());
    // Every servo tick scored, none dropped.
    QCOMPARE(window->ticksDropped(), std::uint64_t{0});
    const std::string ticks = "live " + std::to_string(live.ticks) + " ticks, " +
                              std::to_string(live.contactTicks) + " in contact; headless " +
                              std::to_string(headless.ticks) + ", " +
                              std::to_string(headless.contactTicks);
    // A loaded machine's servo skips late ticks (the replay then reads the next sample): the
    // share of ticks in contact is compared.
    const double liveShare =
      static_cast<double>(live.contactTicks) / static_cast<double>(live.ticks);
    const double headlessShare =
      static_cast<double>(headless.contactTicks) / static_cast<double>(headless.ticks);
    QVERIFY2(std::abs(liveShare - headlessShare) < 0.05, ticks.c_str());
    const std::string peaks =
      std::to_string(live.peakForce) + " N live, " + std::to_string(headless.peakForce) + " N";
    QVERIFY2(std::abs(live.peakForce - headless.peakForce) < 0.15 * headless.peakForce,
             peaks.c_str());
    // Session > Finish (F) shows the score; the dialog is read, pictured and closed.
    auto* finish = window->findChild<QAction*>("finishAttempt");
    QVERIFY(finish != nullptr);
    QCOMPARE(finish->shortcut(), QKeySequence(Qt::Key_F));
    QString shown;
    QTimer::singleShot(300, [&] {
      if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()))
      {
        shown = box->text();
        saveFigure(box, "trainer-window-score.png");
        box->done(QMessageBox::Close);
      }
    });
    finish->trigger();
    QVERIFY2(
      shown.startsWith("Liver targets: touch A, B and C in order: passed\n1 of 1 tasks passed, "
                       "0 damage events"),
      qPrintable(shown));
    QVERIFY2(shown.contains("targets: 3 of 3 touched"), qPrintable(shown));
    QCOMPARE(live.tasks[0].targets.touchedTimes.size(),
             headless.tasks[0].targets.touchedTimes.size());
    // The window scored every tick the servo ran, as a scorer given the same ticks afterwards
    // does, bit for bit: the live scoring is the headless scorer's.
    QCOMPARE(static_cast<std::uint64_t>(ticksScored.size()), live.ticks);
    {
      const LoadedScene loaded = loadExerciseScene(exerciseRunSettings(exercise, ""));
      ExerciseScorer rescorer(exercise, *loaded.scene);
      for (const HapticState& tick : ticksScored)
      {
        rescorer.addTick(tick);
      }
      const ExerciseScore again = rescorer.score();
      QCOMPARE(again.passed, live.passed);
      QCOMPARE(again.contactTicks, live.contactTicks);
      QCOMPARE(again.peakForce, live.peakForce);
      QVERIFY(again.tasks[0].targets.touchedTimes == live.tasks[0].targets.touchedTimes);
    }
    // Against the headless session (lockstep, unbudgeted): each target's hold ends within 0.1 s
    // of the headless one's while the live ticks around it ran undisturbed (they lag by about a
    // tick). A loaded machine disturbs them: the proxy loop stops at the tick budget, the servo
    // skips late ticks or fades a stale proxy's force, and a force out of the target's band for
    // one tick starts the hold again. Then the hold may end later by at most the hold itself plus
    // the seconds disturbed.
    const double hold = exercise.tasks[0].targets.holdSeconds;
    for (std::size_t i = 0; i < live.tasks[0].targets.touchedTimes.size(); ++i)
    {
      const double liveTime = live.tasks[0].targets.touchedTimes[i];
      const double headlessTime = headless.tasks[0].targets.touchedTimes[i];
      const double disturbed =
        disturbedSeconds(ticksScored, std::min(liveTime, headlessTime) - hold - 0.1,
                         std::max(liveTime, headlessTime), period);
      const double later = disturbed > 0.0 ? hold + disturbed : 0.0;
      const std::string times = "target " + std::to_string(i) + ": live " +
                                std::to_string(liveTime) + " s, headless " +
                                std::to_string(headlessTime) + " s, " + std::to_string(disturbed) +
                                " s of live ticks disturbed";
      QVERIFY2(liveTime - headlessTime > -0.1 && liveTime - headlessTime < 0.1 + later,
               times.c_str());
    }
  }

  // The soft kidney's exercise (Data/Scenes/kidney-tissue.json): the window's loops step the
  // solid, so its passing path, which presses each pole 6 mm past first touch, passes live with
  // no damage as it does headless. Rigid, the same press would push back with 3 N, over the
  // exercise's 0.4 N limit.
  void aSoftKidneyIsPressedLiveAsTheHeadlessSessionPressesIt()
  {
    std::shared_ptr<TissueDynamics> tissue;
    auto window =
      openExercise<TickKeepingTrainerWindow>("kidney-press", "mouse", 800, 600, &tissue);
    QVERIFY(window != nullptr);
    QVERIFY(tissue != nullptr);
    const Exercise& exercise = window->exercise();
    const std::string recording = kOutput + "/kidney-press-pass.recording.csv";
    const FingerPath path = readFingerPathFile(kPaths + "/kidney-press-pass.csv");
    std::string error;
    QVERIFY2(writePathAsRecording(path, exercise.rate, recording, error), error.c_str());
    const ExerciseScore headless = playHeadlessSession(exercise, path, "kidney-press-pass.csv", {});
    QVERIFY(headless.passed);
    QCOMPARE(headless.damage.size(), std::size_t{0});
    bool pictured = false;
    const auto pictureTheFirstPress = [&] {
      if (!pictured && window->score().tasks[0].targets.touched == 1)
      {
        saveFigure(window.get(), "trainer-window-kidney.png");
        pictured = true;
      }
    };
    ExerciseScore live;
    std::vector<HapticState> ticksScored;
    std::string why;
    QVERIFY2(replayUntilHeadlessOutcome(*window, recording, path, headless, pictureTheFirstPress,
                                        live, ticksScored, why),
             why.c_str());
    QCOMPARE(window->ticksDropped(), std::uint64_t{0});
    const double disturbed =
      disturbedSeconds(ticksScored, 0.0, path.endTime() + 0.3, 1.0 / exercise.rate);
    const std::string peaks = std::to_string(live.peakForce) + " N live, " +
                              std::to_string(headless.peakForce) + " N headless, " +
                              std::to_string(disturbed) + " s of live ticks disturbed";
    QVERIFY2(live.peakForce < exercise.tissues[0].forceLimit, peaks.c_str());
    // Undisturbed, the live press is the headless one's within 15 %. A loaded machine that held
    // the solid's thread off left the proxy on a surface that had not yet given way, which
    // pushes back harder (0.38 N against 0.30 N in a loaded CI run): then the live peak is only
    // bounded by the damage limit above, and from below as undisturbed.
    QVERIFY2(live.peakForce > 0.85 * headless.peakForce, peaks.c_str());
    if (disturbed == 0.0)
    {
      QVERIFY2(live.peakForce < 1.15 * headless.peakForce, peaks.c_str());
    }
    qInfo("soft kidney: passed live and headless, no damage; peak force %s", peaks.c_str());
  }

  void aRecordedSessionReplaysAndAMissingDeviceKeepsTheMouse()
  {
    auto window = openExercise("liver-palpation", "mouse");
    QVERIFY(window != nullptr);
    std::string error;
    QVERIFY(!window->useDevice("spacemouse", error));
    QVERIFY2(error.find("spacemouse") != std::string::npos, error.c_str());
    QCOMPARE(window->deviceSpec(), std::string("mouse"));

    window->startRecording();
    QVERIFY(window->isRecording());
    QWidget* view = window->view();
    QTest::mouseMove(view, QPoint(view->width() / 2, view->height() / 2));
    QVERIFY(waitUntil([&] { return window->latestState().time > 0.5; }, 30.0));
    const std::string file = kOutput + "/window-session.csv";
    std::filesystem::remove(file);
    QVERIFY2(window->saveRecording(file, error), error.c_str());
    QVERIFY(!window->isRecording());
    QVERIFY(std::filesystem::file_size(file) > 100);
    // A file that cannot be written is an error, and nothing is left behind.
    window->startRecording();
    QVERIFY(!window->saveRecording(kOutput + "/no-such-folder/session.csv", error));
    QVERIFY(!std::filesystem::exists(kOutput + "/no-such-folder"));
    QVERIFY(window->isRecording());

    QVERIFY2(window->useDevice("replay:" + file, error), error.c_str());
    QCOMPARE(window->deviceSpec(), "replay:" + file);
    QVERIFY(waitUntil([&] { return window->ticksSeen() > 100; }, 30.0));
    // Past its end the replay is a device gone: the finger is refused, the proxy holds.
    QVERIFY(waitUntil(
      [&] { return window->latestState().conditions.has(TickCondition::fingerRefused); }, 30.0));
  }
};

int main(int argc, char** argv)
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  // Problems go to the status bar only: nobody is there to close a dialog.
  qputenv("PROXIMA_NO_DIALOGS", "1");
  QApplication application(argc, argv);
  std::filesystem::create_directories(kOutput);
  TrainerWindowTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "TestTrainerWindow.moc"
