#include "window.hpp"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>

namespace clrt::view {
namespace {

std::optional<Key> key_of(const SDL_Keysym& key) {
  switch (key.sym) {
    case SDLK_PLUS: case SDLK_EQUALS: case SDLK_KP_PLUS: return Key::ExposureUp;
    case SDLK_MINUS: case SDLK_KP_MINUS: return Key::ExposureDown;
    case SDLK_0: return Key::ExposureReset;
    case SDLK_g: return Key::Gamma;
    case SDLK_e: return Key::Srgb;
    case SDLK_f: return Key::Filmic;
    case SDLK_SPACE: return Key::PlayPause;
    case SDLK_RIGHT: return Key::NextFrame;
    case SDLK_LEFT: return Key::PreviousFrame;
    case SDLK_TAB: return Key::Flip;
    case SDLK_d: return Key::Difference;
    case SDLK_s: return Key::SideBySide;
    case SDLK_RIGHTBRACKET: return Key::ZoomIn;
    case SDLK_LEFTBRACKET: return Key::ZoomOut;
    case SDLK_z: return Key::ZoomToFit;
    case SDLK_q: case SDLK_ESCAPE: return Key::Quit;
    default: return std::nullopt;
  }
}

class Window {
 public:
  // SDL and the display; the window opens with open(), once its size is known from the screen's.
  Window() {
    if (SDL_Init(SDL_INIT_VIDEO) != 0) throw std::runtime_error(SDL_GetError());
    // Without a display SDL falls back to drivers that draw nowhere: a window nobody sees would
    // keep clrt --preview streaming into it, and the user waiting for it.
    const std::string driver = SDL_GetCurrentVideoDriver();
    if (driver == "offscreen" || driver == "dummy" || driver == "evdev") {
      SDL_Quit();
      throw std::runtime_error("no display (SDL found only its " + driver + " video driver)");
    }
  }
  ~Window() {
    if (window_) SDL_DestroyWindow(window_);
    SDL_Quit();
  }

  // The first display's usable bounds (without panels and docks), less room for the window's
  // frame and title bar, which SDL cannot tell before a window exists.
  ScreenArea screen() const {
    SDL_Rect bounds{};
    if (SDL_GetDisplayUsableBounds(0, &bounds) != 0) return kFirstWindow;
    return {std::max(1, bounds.w - kWindowFrame.width), std::max(1, bounds.h - kWindowFrame.height)};
  }

  // At its first picture's size: without a window manager, one that grows later can reach past
  // the screen's edge.
  void open(int width, int height) {
    window_ = SDL_CreateWindow("clrt-view", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                               width, height, 0);
    if (!window_) throw std::runtime_error(SDL_GetError());
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // The canvas, copied as it is: no scaling or filtering by SDL, so the screen holds exactly the
  // pixels compose() gave.
  void show(const Canvas& canvas, const std::string& title) {
    int width = 0, height = 0;
    SDL_GetWindowSize(window_, &width, &height);
    if (width != canvas.width || height != canvas.height)
      SDL_SetWindowSize(window_, canvas.width, canvas.height);
    SDL_SetWindowTitle(window_, ("clrt-view: " + title).c_str());
    SDL_Surface* screen = SDL_GetWindowSurface(window_);
    SDL_Surface* source = SDL_CreateRGBSurfaceWithFormatFrom(
        const_cast<std::uint32_t*>(canvas.pixels.data()), canvas.width, canvas.height, 32,
        canvas.width * 4, SDL_PIXELFORMAT_RGB888);
    if (screen && source) {
      SDL_SetSurfaceBlendMode(source, SDL_BLENDMODE_NONE);
      SDL_BlitSurface(source, nullptr, screen, nullptr);
      SDL_UpdateWindowSurface(window_);
    }
    SDL_FreeSurface(source);
  }

 private:
  SDL_Window* window_ = nullptr;
};

}  // namespace

int run_window(ViewSources& sources, const ViewNames& names, ViewState state,
               std::optional<double> zoom, Playback playback, PreviewFeed* feed) {
  std::optional<Window> window;
  try {
    window.emplace();
    state.screen = window->screen();
    state.zoom = zoom.value_or(zoom_to_fit(state, sources));
    const Layout first = layout_view(state, sources);
    window->open(first.width, first.height);
  } catch (const std::exception& error) {
    std::cerr << "clrt-view: error: cannot open a window: " << error.what() << "\n";
    return 1;
  }
  if (feed) feed->send_ready();
  // Where the mouse is, while it is over the window.
  bool mouse_in = false;
  SDL_Point mouse{};
  bool dirty = true, ended = false;
  auto last = std::chrono::steady_clock::now();
  for (;;) {
    SDL_Event event;
    while (SDL_WaitEventTimeout(&event, 10)) {
      if (event.type == SDL_QUIT) return 0;
      if (event.type == SDL_KEYDOWN) {
        const std::optional<Key> key = key_of(event.key.keysym);
        if (key && !apply_key(*key, state, playback, sources)) return 0;
        dirty |= key.has_value();
      } else if (event.type == SDL_MOUSEMOTION) {
        mouse = {event.motion.x, event.motion.y};
        mouse_in = true;
        dirty = true;
      } else if (event.type == SDL_WINDOWEVENT) {
        if (event.window.event == SDL_WINDOWEVENT_LEAVE) mouse_in = false;
        dirty = true;
      }
    }
    const auto now = std::chrono::steady_clock::now();
    const int frame = playback.advance(state.frame, sources.frame_count(),
                                       std::chrono::duration<double>(now - last).count());
    last = now;
    dirty |= frame != state.frame;
    state.frame = frame;
    if (feed) {
      dirty |= feed->take(sources.a.front());
      if (feed->ended() && !ended) ended = dirty = true;
    }
    if (!dirty) continue;
    dirty = false;
    const Layout layout = layout_view(state, sources);
    const std::optional<PixelHit> hit =
        mouse_in ? hit_pixel(layout, mouse.x, mouse.y) : std::nullopt;
    std::string title = readout_text(names, sources, state, playback.playing, hit);
    if (feed) title += ended ? " | render complete" : " | rendering";
    window->show(compose(layout, state, sources), title);
  }
}

}  // namespace clrt::view
