#pragma once
// For the `confvis view` tests: an X display to open windows on (the caller's DISPLAY, or an
// Xvfb of our own on a free display number), and what a window manager or a user does to a
// window (resize, close), done through Xlib from outside the process under test; and head poses
// sent to a tracker port on 127.0.0.1.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>

namespace confvis::testing {

class VirtualDisplay {
 public:
  // The display every view test shares; started once, stopped at exit.
  static VirtualDisplay& shared() {
    static VirtualDisplay display;
    return display;
  }
  // Empty when there is no display and no Xvfb binary (the tests then skip).
  const std::string& name() const { return name_; }
  std::string environment() const { return "DISPLAY=" + name_; }
  std::string whyUnavailable() const { return why_; }

  ~VirtualDisplay() {
    if (server_ > 0) {
      ::kill(server_, SIGTERM);
      ::waitpid(server_, nullptr, 0);
    }
  }

 private:
  VirtualDisplay() {
    if (const char* existing = std::getenv("DISPLAY"); existing && *existing) {
      name_ = existing;
      return;
    }
    const char* xvfb = "/usr/bin/Xvfb";
    if (::access(xvfb, X_OK) != 0) {
      why_ = "no DISPLAY and no /usr/bin/Xvfb (Debian: xvfb)";
      return;
    }
    // -displayfd: Xvfb picks a free display number itself and writes it to the pipe once it
    // accepts clients (guessing a number could reach another user's server through Linux's
    // abstract socket namespace, which leaves no file in /tmp/.X11-unix).
    int fds[2];
    if (::pipe(fds) != 0) {
      why_ = "pipe() failed";
      return;
    }
    server_ = ::fork();
    if (server_ == 0) {
      ::close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      ::execl(xvfb, "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "2048x1536x24",
              "-nolisten", "tcp", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    std::string number;
    char c = 0;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) {
      name_ = ":" + number;
      return;
    }
    ::kill(server_, SIGTERM);
    ::waitpid(server_, nullptr, 0);
    server_ = -1;
    why_ = "Xvfb did not start (no display number came back from -displayfd)";
  }

  std::string name_, why_;
  pid_t server_ = -1;
};

// A top-level window whose WM_CLASS name (GLFW: the title it was created with) starts with
// `prefix`, on `display`; nullopt until one exists.
inline std::optional<Window> findWindow(Display* display, const std::string& prefix) {
  Window root = 0, parent = 0, *children = nullptr;
  unsigned count = 0;
  if (!XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count))
    return std::nullopt;
  std::optional<Window> found;
  for (unsigned i = 0; i < count && !found; ++i) {
    XClassHint hint{};
    if (XGetClassHint(display, children[i], &hint)) {
      if (hint.res_name && std::string(hint.res_name).rfind(prefix, 0) == 0) found = children[i];
      if (hint.res_name) XFree(hint.res_name);
      if (hint.res_class) XFree(hint.res_class);
    }
  }
  if (children) XFree(children);
  return found;
}

inline std::optional<Window> waitForWindow(Display* display, const std::string& prefix,
                                           double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (auto window = findWindow(display, prefix)) return window;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return std::nullopt;
}

// Waits until `window` shows a pixel that is not black: the view has presented a frame there, so
// its start-up (pipelines, first map) is over. False after `seconds` without one. X errors
// (the window not viewable yet) are ignored meanwhile instead of ending the test process.
inline bool waitForDrawnPixels(Display* display, Window window, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  XErrorHandler previous = XSetErrorHandler([](Display*, XErrorEvent*) { return 0; });
  bool drawn = false;
  while (!drawn && std::chrono::steady_clock::now() < end) {
    XWindowAttributes attributes{};
    if (XGetWindowAttributes(display, window, &attributes) && attributes.map_state == IsViewable) {
      if (XImage* image = XGetImage(display, window, 0, 0, attributes.width, attributes.height,
                                    AllPlanes, ZPixmap)) {
        for (int y = 0; y < image->height && !drawn; ++y)
          for (int x = 0; x < image->width && !drawn; ++x) drawn = XGetPixel(image, x, y) != 0;
        XDestroyImage(image);
      }
    }
    XSync(display, False);
    if (!drawn) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  XSetErrorHandler(previous);
  return drawn;
}

// What a window manager sends when the user clicks a window's close button.
inline void requestClose(Display* display, Window window) {
  XEvent event{};
  event.xclient.type = ClientMessage;
  event.xclient.window = window;
  event.xclient.message_type = XInternAtom(display, "WM_PROTOCOLS", False);
  event.xclient.format = 32;
  event.xclient.data.l[0] = static_cast<long>(XInternAtom(display, "WM_DELETE_WINDOW", False));
  event.xclient.data.l[1] = CurrentTime;
  XSendEvent(display, window, False, NoEventMask, &event);
  XFlush(display);
}

// Starts `command` (a shell line) in the background; its output goes to `log`.
inline pid_t startBackground(const std::string& command, const std::filesystem::path& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string line = "exec " + command + " > '" + log.string() + "' 2>&1";
    ::execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

// The exit code of `pid`, or nullopt if it is still running after `seconds` (then killed).
inline std::optional<int> waitExit(pid_t pid, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (::waitpid(pid, &status, WNOHANG) == pid)
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return std::nullopt;
}

// A UDP port on 127.0.0.1 that was free a moment ago (for `--tracker udp:PORT`).
inline int freeUdpPort() {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
  socklen_t length = sizeof address;
  ::getsockname(s, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(s);
  return ntohs(address.sin_port);
}

inline void sendTo(int port, const std::string& datagram) {
  const int s = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::sendto(s, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr*>(&address),
           sizeof address);
  ::close(s);
}

}  // namespace confvis::testing
