// clrt-view's logic without a window: tone mapping, layout and the pixel under the mouse, the
// readout, playback and the keys.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "controls.hpp"
#include "readout.hpp"

using namespace clrt;
using namespace clrt::view;

namespace {

const FloatImage kTwoByOne{2, 1, {0.25f, 0.5f, 1.5f, -1.0f, 0.0f, 0.75f}};

}  // namespace

TEST_CASE("tone mapping at exposure 0 and gamma 1 gives the bytes clrt's PNG holds",
          "[view][tone]") {
  const FloatImage image{4, 1, {0.0f, 0.001f, 0.5f, 0.999f, 1.0f, 7.0f, -3.0f,
                                std::numeric_limits<float>::quiet_NaN(),
                                std::numeric_limits<float>::infinity(), 0.3f, 0.6f, 0.9f}};
  const Rgba8Image bytes = quantize(image);
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t pixel = tone_map_pixel(&image.rgb[3 * i], {});
    CHECK((pixel >> 16) == bytes.frames[0][4 * i]);
    CHECK(((pixel >> 8) & 0xff) == bytes.frames[0][4 * i + 1]);
    CHECK((pixel & 0xff) == bytes.frames[0][4 * i + 2]);
  }
}

TEST_CASE("exposure doubles per stop and gamma encodes, worked by hand", "[view][tone]") {
  CHECK(display_byte(0.25f, {1, 1}) == 128);       // 0.5 * 255 = 127.5, rounded up
  CHECK(display_byte(0.25f, {-1, 1}) == 32);       // 0.125 * 255 = 31.9
  CHECK(display_byte(0.5f, {0, 2.2}) == 186);      // 0.5^(1/2.2) = 0.7297
  CHECK(display_byte(0.25f, {1, 2.2}) == 186);
  CHECK(display_byte(3.0f, {0, 2.2}) == 255);      // clamped before the power
  CHECK(display_byte(-0.5f, {2, 2.2}) == 0);
  CHECK(display_byte(std::nanf(""), {1, 2.2}) == 0);
}

TEST_CASE("sRGB and the filmic curve on the screen are the bytes clrt's writers give",
          "[view][tone]") {
  const FloatImage image{3, 1, {0.0f, 0.001f, 0.5f, 0.18f, 1.0f, 7.0f, -3.0f, 0.3f, 0.9f}};
  for (const ToneSettings& tone : {ToneSettings{0, 1, ToneCurve::Clamp, true},
                                   ToneSettings{1, 1, ToneCurve::Filmic, false},
                                   ToneSettings{-0.5, 1, ToneCurve::Filmic, true}}) {
    const Rgba8Image bytes = quantize(image, tone);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t pixel = tone_map_pixel(&image.rgb[3 * i], tone);
      CHECK((pixel >> 16) == bytes.frames[0][4 * i]);
      CHECK(((pixel >> 8) & 0xff) == bytes.frames[0][4 * i + 1]);
      CHECK((pixel & 0xff) == bytes.frames[0][4 * i + 2]);
    }
  }
  CHECK(display_byte(0.5f, {0, 1, ToneCurve::Clamp, true}) == 188);   // 0.7354 * 255
  CHECK(display_byte(0.5f, {0, 2.2, ToneCurve::Clamp, true}) == 188);  // sRGB, not the gamma
}

TEST_CASE("layout: one picture, or A and B side by side with their difference, and the pixel "
          "under a point",
          "[view][layout]") {
  const AnyImage b = FloatImage{2, 1, {0.25f, 0.5f, 1.0f, -1.0f, 0.0f, 0.75f}};
  const ViewSources sources = make_sources(kTwoByOne, &b);
  ViewState state;
  state.zoom = 10;
  Layout layout = layout_view(state, sources);
  CHECK(layout.width == 20);
  CHECK(layout.height == 10);
  REQUIRE(layout.places.size() == 1);
  CHECK(layout.places[0].picture == Picture::A);

  state.side_by_side = state.show_difference = true;
  layout = layout_view(state, sources);
  CHECK(layout.width == 3 * 20 + 2 * kGap);
  REQUIRE(layout.places.size() == 3);
  CHECK(layout.places[2].picture == Picture::Difference);
  CHECK(layout.places[2].x == 2 * (20 + kGap));

  const auto hit = hit_pixel(layout, 20 + kGap + 15, 9);
  REQUIRE(hit);
  CHECK(hit->picture == Picture::B);
  CHECK(hit->x == 1);
  CHECK(hit->y == 0);
  CHECK_FALSE(hit_pixel(layout, 20, 5));  // the gap
  CHECK_FALSE(hit_pixel(layout, 5, 10));  // below

  const Canvas canvas = compose(layout, state, sources);
  CHECK(canvas.at(20, 0) == kBackground);
  CHECK(canvas.at(2 * (20 + kGap), 0) == 0x0000ffU);  // only blue of pixel 0 differs: 1 after scaling
  CHECK(canvas.at(2 * (20 + kGap) + 10, 0) == 0x000000U);
}

TEST_CASE("zoom by any factor: a reduced picture shows the mean radiance of what it covers",
          "[view][layout]") {
  // 4x2: the columns' values 0, 1, 2, 3 in red, the rows' 0 and 0.5 in green.
  std::vector<float> rgb;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) rgb.insert(rgb.end(), {float(x) / 4, float(y) / 2, 0});
  const ViewSources sources = make_sources(FloatImage{4, 2, rgb}, nullptr);
  ViewState state;
  state.zoom = 0.5;
  const Layout half = layout_view(state, sources);
  CHECK((half.width == 2 && half.height == 1));
  const Canvas reduced = compose(half, state, sources);
  // Pixel 0 covers columns 0 and 1 of both rows: red (0 + 0.25) / 2, green 0.25.
  const float first[3] = {0.125f, 0.25f, 0};
  CHECK(reduced.at(0, 0) == tone_map_pixel(first, state.tone));
  const float second[3] = {0.625f, 0.25f, 0};
  CHECK(reduced.at(1, 0) == tone_map_pixel(second, state.tone));
  const auto hit = hit_pixel(half, 1, 0);
  REQUIRE(hit);
  CHECK((hit->x == 2 && hit->y == 0));

  // 1.5x: three screen columns for two image columns, the first image column twice.
  state.zoom = 1.5;
  const Layout magnified = layout_view(state, sources);
  CHECK((magnified.width == 6 && magnified.height == 3));
  const Canvas shown = compose(magnified, state, sources);
  CHECK(shown.at(1, 0) == shown.at(0, 0));
  CHECK(shown.at(2, 0) != shown.at(1, 0));
  CHECK(hit_pixel(magnified, 2, 2)->x == 1);
  CHECK(hit_pixel(magnified, 2, 2)->y == 1);
}

TEST_CASE("the zoom a window opens at fits the screen, and the keys step through whole zooms "
          "and their reciprocals",
          "[view][layout]") {
  const ScreenArea full_hd{1904, 1016};
  CHECK(fitting_zoom(16, 12, 1, full_hd) == 64);           // magnified within 1024x768
  CHECK(fitting_zoom(16, 12, 1, {500, 300}) == 25);        // a small screen's fewer
  CHECK(fitting_zoom(1920, 1080, 1, full_hd) == Approx(1016.0 / 1080));  // reduced to fit
  CHECK(fitting_zoom(3840, 2160, 1, full_hd) == Approx(1016.0 / 2160));
  CHECK(fitting_zoom(1024, 768, 3, full_hd) == Approx((1904.0 - 2 * kGap) / (3 * 1024)));
  CHECK(fitting_zoom(1 << 20, 1, 1, full_hd) == kMinZoom);
  CHECK(zoom_in(1) == 2);
  CHECK(zoom_in(2.5) == 3);
  CHECK(zoom_out(2.5) == 2);
  CHECK(zoom_out(1) == 0.5);
  CHECK(zoom_out(0.5) == Approx(1.0 / 3));
  CHECK(zoom_in(1.0 / 3) == 0.5);
  CHECK(zoom_in(0.4) == 0.5);
  CHECK(zoom_out(0.4) == Approx(1.0 / 3));
  CHECK(zoom_in(0.5) == 1);
  CHECK(zoom_out(kMinZoom) == kMinZoom);
  CHECK(zoom_in(kMaxZoom) == kMaxZoom);
}

TEST_CASE("showing more pictures side by side lowers the zoom until they fit the screen",
          "[view][layout]") {
  const FloatImage wide{800, 10, std::vector<float>(3 * 800 * 10, 0.5f)};
  const AnyImage b = wide;
  const ViewSources sources = make_sources(wide, &b);
  ViewState state;
  state.screen = {1000, 700};
  state.zoom = 1;
  Playback playback;
  apply_key(Key::SideBySide, state, playback, sources);
  CHECK(layout_view(state, sources).width <= 1000);
  CHECK(state.zoom == Approx((1000.0 - kGap) / 1600));
  apply_key(Key::SideBySide, state, playback, sources);  // one picture again: the zoom stays
  CHECK(state.zoom == Approx((1000.0 - kGap) / 1600));
  apply_key(Key::ZoomToFit, state, playback, sources);
  CHECK(state.zoom == 1);
}

TEST_CASE("a float image holds linear values, an 8-bit one display bytes", "[view][tone]") {
  CHECK(make_sources(kTwoByOne, nullptr).linear);
  CHECK_FALSE(make_sources(Rgba8Image(1, 1, {{1, 2, 3, 255}}), nullptr).linear);
}

TEST_CASE("images of different sizes cannot be compared", "[view][layout]") {
  const AnyImage b = FloatImage{1, 1, {0, 0, 0}};
  CHECK_THROWS_AS(make_sources(kTwoByOne, &b), ImageError);
}

TEST_CASE("the readout names the pictures, the frame, the tone and the values under the mouse",
          "[view][readout]") {
  const AnyImage b = FloatImage{2, 1, {0.25f, 0.5f, 1.0f, -1.0f, 0.0f, 0.75f}};
  const ViewSources sources = make_sources(kTwoByOne, &b);
  ViewState state;
  state.tone = {1.5, 2.2};
  CHECK(readout_text({"a.pfm", "b.pfm"}, sources, state, true, std::nullopt) ==
        "A: a.pfm | exposure +1.5 gamma 2.2 | zoom 1x");
  state.flipped = Picture::B;
  CHECK(readout_text({"a.pfm", "b.pfm"}, sources, state, true, PixelHit{Picture::B, 0, 0}) ==
        "B: b.pfm | exposure +1.5 gamma 2.2 | zoom 1x | (0, 0) A 0.25 0.5 1.5 B 0.25 0.5 1 diff 0 0 1");

  const Rgba8Image animation{1, 1, {{0, 0, 0, 255}, {255, 0, 0, 255}, {0, 0, 255, 255}}};
  const ViewSources frames = make_sources(animation, nullptr);
  state = {};
  state.frame = 1;
  state.zoom = 1.0 / 3;
  CHECK(readout_text({"turn.fsf", ""}, frames, state, false, std::nullopt) ==
        "turn.fsf | frame 2/3 paused | exposure +0.0 gamma 1.0 | zoom 0.333x");
  state.tone.curve = ToneCurve::Filmic;
  state.tone.srgb = true;
  CHECK(readout_text({"turn.fsf", ""}, frames, state, false, std::nullopt) ==
        "turn.fsf | frame 2/3 paused | exposure +0.0 filmic sRGB | zoom 0.333x");
}

TEST_CASE("playback advances by the frame rate and loops, a step by hand pauses it",
          "[view][controls]") {
  Playback playback;
  playback.fps = 10;
  int frame = 0;
  frame = playback.advance(frame, 3, 0.05);
  CHECK(frame == 0);
  frame = playback.advance(frame, 3, 0.06);  // 0.11 s: one period
  CHECK(frame == 1);
  frame = playback.advance(frame, 3, 0.2);   // two more: past the last, back to 0
  CHECK(frame == 0);

  const Rgba8Image animation{1, 1, {{0, 0, 0, 255}, {255, 0, 0, 255}, {0, 0, 255, 255}}};
  const ViewSources sources = make_sources(animation, nullptr);
  ViewState state;
  CHECK(apply_key(Key::PreviousFrame, state, playback, sources));
  CHECK(state.frame == 2);
  CHECK_FALSE(playback.playing);
  CHECK(playback.advance(state.frame, 3, 1.0) == 2);
  apply_key(Key::NextFrame, state, playback, sources);
  CHECK(state.frame == 0);
  apply_key(Key::PlayPause, state, playback, sources);
  CHECK(playback.playing);
}

TEST_CASE("keys: exposure, gamma, sRGB, filmic, flip, difference, side by side, zoom, quit", "[view][controls]") {
  const AnyImage b = kTwoByOne;
  const ViewSources two = make_sources(kTwoByOne, &b), one = make_sources(kTwoByOne, nullptr);
  ViewState state;
  Playback playback;
  apply_key(Key::ExposureUp, state, playback, two);
  apply_key(Key::ExposureUp, state, playback, two);
  apply_key(Key::ExposureDown, state, playback, two);
  CHECK(state.tone.exposure == kExposureStep);
  apply_key(Key::Gamma, state, playback, two);
  CHECK(state.tone.gamma == kDisplayGamma);
  apply_key(Key::Srgb, state, playback, two);
  CHECK(state.tone.srgb);
  apply_key(Key::Filmic, state, playback, two);
  CHECK(state.tone.curve == ToneCurve::Filmic);
  apply_key(Key::Gamma, state, playback, two);  // back to gamma 1, and sRGB off
  CHECK((state.tone.gamma == 1 && !state.tone.srgb));
  apply_key(Key::Srgb, state, playback, two);
  apply_key(Key::ExposureReset, state, playback, two);
  CHECK(state.tone.identity());
  apply_key(Key::Flip, state, playback, two);
  CHECK(state.flipped == Picture::B);
  apply_key(Key::Difference, state, playback, two);
  apply_key(Key::SideBySide, state, playback, two);
  CHECK((state.show_difference && state.side_by_side));
  ViewState alone;
  apply_key(Key::Flip, alone, playback, one);
  apply_key(Key::SideBySide, alone, playback, one);
  CHECK((alone.flipped == Picture::A && !alone.side_by_side));  // nothing to compare with
  apply_key(Key::ZoomOut, alone, playback, one);
  CHECK(alone.zoom == 0.5);
  apply_key(Key::ZoomIn, alone, playback, one);
  apply_key(Key::ZoomIn, alone, playback, one);
  CHECK(alone.zoom == 2);
  CHECK_FALSE(apply_key(Key::Quit, alone, playback, one));
}
