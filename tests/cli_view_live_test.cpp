// `confvis view` under what a live display meets (Xvfb, lavapipe): a window minimised and
// restored (the window manager's WM_STATE, set from outside as one would), a window whose
// surface reports 0 x 0 for some frames (injected: Xvfb never does), and head poses fed over UDP
// to 127.0.0.1 in both protocols, with garbage among them.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_support.hpp"
#include "confvis/base/atomic_file.hpp"
#include "view_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::scratch;
using confvis::testing::freeUdpPort;
using confvis::testing::sendTo;
using confvis::testing::VirtualDisplay;

namespace {

std::string cave6() { return std::string(CONFVIS_SOURCE_DIR) + "/configs/cave6.json"; }

// ICCCM WM_STATE, which a window manager sets when it iconifies or restores a window (GLFW
// reads it for GLFW_ICONIFIED; Xvfb runs no window manager, so the test plays that part).
void setWmState(Display* display, Window window, long state) {
  const Atom wmState = XInternAtom(display, "WM_STATE", False);
  const long data[2] = {state, 0};  // state, icon window
  XChangeProperty(display, window, wmState, wmState, 32, PropModeReplace,
                  reinterpret_cast<const unsigned char*>(data), 2);
  XFlush(display);
}
constexpr long kNormalState = 1, kIconicState = 3;

struct Background {
  pid_t pid;
  fs::path out, log;
};

Background startView(const std::string& name, const std::string& args) {
  Background run{0, scratch("view-" + name), scratch("view-" + name + ".log")};
  run.pid = confvis::testing::startBackground(
      "env " + VirtualDisplay::shared().environment() + " " + CONFVIS_CLI_PATH + " view " +
          cave6() + " " + args + " -q -o " + run.out.string(),
      run.log);
  return run;
}

// Closes the front window and returns view.json (the run must have ended with exit 0).
nlohmann::json closeAndReport(Display* display, Window front, const Background& run) {
  confvis::testing::requestClose(display, front);
  const std::optional<int> exitCode = confvis::testing::waitExit(run.pid, 60.0);
  EXPECT_TRUE(exitCode) << "still running after the close: " << confvis::readTextFile(run.log);
  EXPECT_EQ(exitCode.value_or(-1), 0) << confvis::readTextFile(run.log);
  return nlohmann::json::parse(confvis::readTextFile(run.out / "view.json"));
}

void sleepSeconds(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }

// The frame log shows all `windows` presented, then one fewer for a while (never anything else
// meanwhile), then all again. Returns the first frame of each phase (-1 if not reached).
std::array<int, 2> expectOneWindowPausedAndResumed(const nlohmann::json& report, int windows) {
  int phase = 0;  // 0: before, 1: one window paused, 2: resumed
  std::array<int, 2> starts{-1, -1};
  for (const nlohmann::json& frame : report["frames"]) {
    const int shown = frame["windows_presented"], index = frame["frame"];
    if (phase == 0 && shown == windows - 1) {
      phase = 1;
      starts[0] = index;
    }
    if (phase == 1 && shown == windows) {
      phase = 2;
      starts[1] = index;
    }
    if (phase == 1) {
      EXPECT_EQ(shown, windows - 1) << "frame " << frame["frame"];
    }
  }
  EXPECT_EQ(phase, 2) << "the window paused and resumed";
  return starts;
}

void expectNoValidationMessage(const nlohmann::json& report) {
  EXPECT_TRUE(report["validation"]["enabled"].get<bool>());
  EXPECT_EQ(report["validation"]["errors"], 0) << report["validation"].dump(2);
  EXPECT_EQ(report["validation"]["warnings"], 0) << report["validation"].dump(2);
}

// The shared display, retried for a few seconds (a loaded machine can refuse the first try).
Display* openDisplay() {
  for (int attempt = 0; attempt < 50; ++attempt) {
    if (Display* display = XOpenDisplay(VirtualDisplay::shared().name().c_str())) return display;
    sleepSeconds(0.2);
  }
  return nullptr;
}

}  // namespace

// The front window minimised for a second: its swapchain presents nothing meanwhile (the other
// five windows go on), then the frames come back; the validation layer reports nothing.
TEST(CliViewLive, MinimisedWindowPausesAndResumesWithoutValidationMessages) {
  if (VirtualDisplay::shared().name().empty()) GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable();
  for (const std::string backend : {"vulkan", "embree"}) {
    SCOPED_TRACE(backend);
    Display* display = openDisplay();  // before the run starts: a failed ASSERT leaves none
    ASSERT_NE(display, nullptr);
    const Background run =
        startView("iconify-" + backend, "--backend " + backend + " --scale 0.05 --validate");
    const auto front = confvis::testing::waitForWindow(display, "confvis view: front", 30.0);
    ASSERT_TRUE(front) << "no window appeared: " << confvis::readTextFile(run.log);
    // Minimised only once frames are being drawn: under load the start-up after the window
    // appears can outlast a fixed wait, and then no frame is ever seen paused.
    ASSERT_TRUE(confvis::testing::waitForDrawnPixels(display, *front, 60.0))
        << "the front window never showed a frame: " << confvis::readTextFile(run.log);
    setWmState(display, *front, kIconicState);
    sleepSeconds(1.5);
    setWmState(display, *front, kNormalState);
    sleepSeconds(1.5);
    const nlohmann::json report = closeAndReport(display, *front, run);
    XCloseDisplay(display);

    EXPECT_EQ(report["frame_path"], backend == "vulkan" ? "gpu" : "staging");
    expectNoValidationMessage(report);
    // Six windows, then five while the front one is minimised, then six again.
    expectOneWindowPausedAndResumed(report, 6);
  }
}

// The front window's surface reports 0 x 0 for frames 10 to 17 (as a minimised window's does on
// Windows and some compositors; injected through CONFVIS_TEST_ZERO_EXTENT, since Xvfb never
// does): the presenter skips that window without making a swapchain of zero size, the other five
// go on every frame, and frame 18 shows it again through a new swapchain of the window's size.
// No validation message, both frame paths (GPU frames through acquire(), staged CPU frames).
TEST(CliViewLive, ZeroSurfaceExtentSkipsTheWindowAndRecreatesWithoutValidationMessages) {
  if (VirtualDisplay::shared().name().empty()) GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable();
  constexpr int kFirst = 10, kCount = 8, kFrames = 30;
  for (const std::string backend : {"vulkan", "embree"}) {
    SCOPED_TRACE(backend);
    const fs::path out = scratch("view-zero-extent-" + backend);
    const confvis::testing::CliRun run = confvis::testing::runCli(
        "view " + cave6() + " --backend " + backend + " --scale 0.05 --validate -q --frames " +
            std::to_string(kFrames) + " -o " + out.string(),
        VirtualDisplay::shared().environment() + " CONFVIS_TEST_ZERO_EXTENT=front:" +
            std::to_string(kFirst) + ":" + std::to_string(kCount));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const nlohmann::json report =
        nlohmann::json::parse(confvis::readTextFile(out / "view.json"));

    EXPECT_EQ(report["frame_path"], backend == "vulkan" ? "gpu" : "staging");
    EXPECT_EQ(report["end"], "frames");
    ASSERT_EQ(report["frames"].size(), static_cast<std::size_t>(kFrames)) << "frames went on";
    expectNoValidationMessage(report);
    const std::array<int, 2> starts = expectOneWindowPausedAndResumed(report, 6);
    EXPECT_EQ(starts[0], kFirst);
    EXPECT_EQ(starts[1], kFirst + kCount);
    for (const nlohmann::json& entry : report["windows"]) {
      SCOPED_TRACE(entry["wall"].get<std::string>());
      // One new swapchain for the front window, at its own size again; none for the others.
      EXPECT_EQ(entry["swapchain_recreations"], entry["wall"] == "front" ? 1 : 0);
      EXPECT_EQ(entry["swapchain"], nlohmann::json({96, 96}));
    }
  }
  // A wall the display does not have is one error naming the variable, not a silent no-op.
  const confvis::testing::CliRun unknown = confvis::testing::runCli(
      "view " + cave6() + " --frames 1 -q -o " + scratch("view-zero-extent-bad").string(),
      VirtualDisplay::shared().environment() + " CONFVIS_TEST_ZERO_EXTENT=nowhere:1:2");
  EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("CONFVIS_TEST_ZERO_EXTENT"), std::string::npos) << unknown.output;
  EXPECT_NE(unknown.output.find("nowhere"), std::string::npos) << unknown.output;
}

namespace {

// A pose in the tracker's protocol: metres and an identity rotation (cave6 has no "tracking"
// transform, so the room frame is the tracker's).
std::string pose(const std::string& protocol, int frame, double x, double y, double z) {
  char text[256];
  if (protocol == "udp")
    std::snprintf(text, sizeof text, "{\"t\": %d, \"pos\": [%g, %g, %g], \"quat\": [0, 0, 0, 1]}\n",
                  frame, x, y, z);
  else  // ART DTrack2 ASCII: millimetres, body 0, rotation matrix column-wise
    std::snprintf(text, sizeof text,
                  "fr %d\r\nts %d.0\r\n6dcal 1\r\n6d 1 [0 1.000][%.3f %.3f %.3f 0 0 0]"
                  "[1 0 0 0 1 0 0 0 1]\r\n",
                  frame, frame, 1000 * x, 1000 * y, 1000 * z);
  return text;
}

}  // namespace

// Poses sent to 127.0.0.1 move the views: the frame log's head (from which every eye's
// off-axis frustum is made) follows the fed poses in order; the garbage datagrams are counted as
// dropped and change nothing.
TEST(CliViewLive, UdpPosesInBothProtocolsMoveTheViewsAndGarbageIsCounted) {
  if (VirtualDisplay::shared().name().empty()) GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable();
  const std::vector<std::vector<double>> poses = {{0.05, 0.0, 0.0}, {-0.04, 0.03, 0.02}};
  for (const std::string protocol : {"udp", "dtrack"}) {
    SCOPED_TRACE(protocol);
    const int port = freeUdpPort();
    // Plain mode, 8 cm moves: within the follower's radius, so no re-bake competes for the CPU.
    Display* display = openDisplay();  // before the run starts: a failed ASSERT leaves none
    ASSERT_NE(display, nullptr);
    const Background run = startView("udp-" + protocol, "--backend vulkan --scale 0.02 --mode plain"
                                                        " --tracker " + protocol + ":" +
                                                        std::to_string(port));
    const auto front = confvis::testing::waitForWindow(display, "confvis view: front", 30.0);
    ASSERT_TRUE(front) << "no window appeared: " << confvis::readTextFile(run.log);
    // Poses only once frames are being drawn: under load (CI's sanitizer builds) the start-up
    // after the window appears can outlast the first pose, whose frames the test counts.
    ASSERT_TRUE(confvis::testing::waitForDrawnPixels(display, *front, 60.0))
        << "the front window never showed a frame: " << confvis::readTextFile(run.log);
    const std::vector<std::string> garbage = {"hello", "{\"pos\": [1, 2", "6d 1 [0 1.0][nan"};
    int frame = 0;
    for (const std::vector<double>& p : poses) {
      for (int i = 0; i < 40; ++i, ++frame) {  // 0.8 s of each pose at 50 Hz
        sendTo(port, pose(protocol, frame, p[0], p[1], p[2]));
        if (i == 10 && &p == &poses.front())
          for (const std::string& g : garbage) sendTo(port, g);
        sleepSeconds(0.02);
      }
    }
    sleepSeconds(0.3);
    const nlohmann::json report = closeAndReport(display, *front, run);
    XCloseDisplay(display);

    EXPECT_EQ(report["tracker"]["packets_dropped"], garbage.size()) << report["tracker"].dump();
    EXPECT_GE(report["tracker"]["packets_received"].get<int>(), 60) << report["tracker"].dump();
    // The head in the log: the reference point until the first pose, then pose 0, then pose 1,
    // never back.
    std::size_t next = 0;
    int framesAtPose[2] = {0, 0};
    for (const nlohmann::json& f : report["frames"]) {
      const std::vector<double> head = f["head"];
      const auto at = [&](std::size_t i) {
        return std::abs(head[0] - poses[i][0]) < 1e-6 && std::abs(head[1] - poses[i][1]) < 1e-6 &&
               std::abs(head[2] - poses[i][2]) < 1e-6;
      };
      if (next < poses.size() && at(next)) ++next;
      const bool known = (next >= 1 && at(next - 1)) ||
                         (next == 0 && std::abs(head[0]) + std::abs(head[1]) + std::abs(head[2]) < 1e-12);
      EXPECT_TRUE(known) << "frame " << f["frame"] << " head " << f["head"].dump();
      if (next >= 1) ++framesAtPose[next - 1];
    }
    EXPECT_EQ(next, poses.size()) << "the views followed both poses in order";
    EXPECT_GE(framesAtPose[0], 3);
    EXPECT_GE(framesAtPose[1], 3);
  }
}
