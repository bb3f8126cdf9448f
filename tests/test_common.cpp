#include "common/FrameFidelity.h"
#include "common/FrameSet.h"
#include "common/KeyValue.h"
#include "common/OverlayLegibility.h"
#include "common/PngImage.h"
#include "common/ProcessName.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

using namespace nprgl;

TEST(FrameSet, ParsesListsRangesAndOpenEnds)
{
    FrameSet set;
    std::string error;
    ASSERT_TRUE(FrameSet::parse("1,10,20-22,100-", set, error)) << error;
    EXPECT_TRUE(set.contains(1));
    EXPECT_FALSE(set.contains(2));
    EXPECT_TRUE(set.contains(10));
    EXPECT_TRUE(set.contains(21));
    EXPECT_FALSE(set.contains(23));
    EXPECT_TRUE(set.contains(1000000));
    EXPECT_EQ(set.last(), UINT64_MAX);
}

TEST(FrameSet, RefusesBadItemsWithAMessage)
{
    FrameSet set;
    std::string error;
    for (const char* bad : {"", "0", "x", "5-3", "1,,a", "-4", "1-2-3", "99999999999999999999"}) {
        error.clear();
        EXPECT_FALSE(FrameSet::parse(bad, set, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(KeyValue, SplitsAndTrims)
{
    KeyValueList list;
    std::string error;
    ASSERT_TRUE(parseKeyValues(" frames=1,2 ; dir = out ", ';', list, error)) << error;
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0], (std::pair<std::string, std::string>{"frames", "1,2"}));
    EXPECT_EQ(list[1], (std::pair<std::string, std::string>{"dir", "out"}));
    EXPECT_FALSE(parseKeyValues("a=1,novalue", ',', list, error));
    EXPECT_NE(error.find("novalue"), std::string::npos);
    EXPECT_FALSE(parseKeyValues("=3", ',', list, error));
}

TEST(PngImage, RoundTripsAndFlips)
{
    PngImage image;
    image.width = 3;
    image.height = 2;
    for (int i = 0; i < 24; ++i) image.rgba.push_back(uint8_t(i * 10));
    std::string path = test::freshDir("png") + "/a.png", error;
    ASSERT_TRUE(image.write(path, error)) << error;
    PngImage back;
    ASSERT_TRUE(PngImage::read(path, back, error)) << error;
    EXPECT_EQ(back.rgba, image.rgba);
    back.flipRows();
    EXPECT_EQ(back.rgba[0], image.rgba[12]);
    EXPECT_FALSE(PngImage::read(path + ".missing", back, error));
    EXPECT_NE(error.find(".missing"), std::string::npos);
}

#include "common/ScreenshotSpec.h"

TEST(ScreenshotSpec, ParsesFramesAndDirAndRefusesTheRest)
{
    ScreenshotSpec spec;
    std::string error;
    ASSERT_TRUE(ScreenshotSpec::parse("frames=1,10;dir=out", spec, error)) << error;
    EXPECT_TRUE(spec.frames.contains(10));
    EXPECT_EQ(spec.dir, "out");
    ASSERT_TRUE(ScreenshotSpec::parse("frames=3", spec, error)) << error;
    EXPECT_EQ(spec.dir, ".");
    EXPECT_FALSE(ScreenshotSpec::parse("dir=out", spec, error));
    EXPECT_NE(error.find("frames=LIST"), std::string::npos) << error;
    EXPECT_FALSE(ScreenshotSpec::parse("frames=1;size=3", spec, error));
    EXPECT_NE(error.find("'size'"), std::string::npos) << error;
    EXPECT_FALSE(ScreenshotSpec::parse("frames=0", spec, error));
}

namespace {

PngImage filled(int w, int h, uint8_t r, uint8_t g, uint8_t b)
{
    PngImage image;
    image.width = w;
    image.height = h;
    image.rgba.resize(size_t(w) * h * 4);
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        image.rgba[i] = r, image.rgba[i + 1] = g, image.rgba[i + 2] = b, image.rgba[i + 3] = 255;
    }
    return image;
}

// Paints the rectangle [x0, x1) x [y0, y1).
void paint(PngImage& image, int x0, int y0, int x1, int y1, const uint8_t rgb[3])
{
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            std::copy(rgb, rgb + 3, &image.rgba[(size_t(y) * image.width + x) * 4]);
        }
    }
}

// A 40x40 frame cleared dark grey with a green square (the program's) at 10..30.
struct Frames {
    const uint8_t green[3] = {39, 183, 39};
    PngImage native = filled(40, 40, 30, 30, 30);
    PngImage ids = filled(40, 40, 30, 30, 30);
    Frames()
    {
        paint(native, 10, 10, 30, 30, green);
        uint8_t id[3];
        FrameFidelity::idColour(1, id);
        paint(ids, 10, 10, 30, 30, id);
    }
};

} // namespace

TEST(FrameFidelity, LabOfKnownColours)
{
    const uint8_t white[3] = {255, 255, 255}, red[3] = {255, 0, 0};
    const Lab w = Lab::fromSrgb(white), r = Lab::fromSrgb(red);
    EXPECT_NEAR(w.l, 100.0f, 0.1f);
    EXPECT_NEAR(w.a, 0.0f, 0.1f);
    EXPECT_NEAR(r.l, 53.24f, 0.1f);
    EXPECT_NEAR(r.a, 80.09f, 0.2f);
    EXPECT_NEAR(r.b, 67.20f, 0.2f);
}

TEST(FrameFidelity, AnIdenticalFrameIsFaithful)
{
    Frames f;
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(f.native, f.native, f.ids, false, m, error)) << error;
    EXPECT_EQ(m.drawn, 400u);
    EXPECT_DOUBLE_EQ(m.fidelity(), 1.0);
    EXPECT_EQ(m.missing, 0u);
    ASSERT_EQ(m.objects.size(), 1u);
    EXPECT_EQ(m.objects[0].pixels, 400u);
    EXPECT_EQ(m.objects[0].box, (std::array<int, 4>{10, 10, 29, 29}));
    EXPECT_TRUE(m.objects[0].paletteOk());
}

TEST(FrameFidelity, AnObjectLostIsMissing)
{
    Frames f;
    // The style drew nothing there, and no object of its covers it.
    const PngImage styled = filled(40, 40, 30, 30, 30);
    const PngImage ids = filled(40, 40, 30, 30, 30);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(f.native, styled, ids, false, m, error)) << error;
    EXPECT_EQ(m.missing, 400u);
    EXPECT_DOUBLE_EQ(m.missingShare(), 1.0);
    EXPECT_DOUBLE_EQ(m.fidelity(), 0.0);
}

TEST(FrameFidelity, AHueChangeFailsThePaletteAndTheFidelity)
{
    Frames f;
    // pymol's defect: carbon green (39,183,39) drawn cyan.
    PngImage styled = f.native;
    const uint8_t cyan[3] = {39, 183, 183};
    paint(styled, 10, 10, 30, 30, cyan);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(f.native, styled, f.ids, true, m, error)) << error;
    EXPECT_DOUBLE_EQ(m.fidelity(), 0.0);
    EXPECT_EQ(m.missing, 0u) << "an object is there, in the wrong colour";
    ASSERT_EQ(m.objects.size(), 1u);
    EXPECT_FALSE(m.objects[0].hueKept);
    EXPECT_EQ(m.paletteFailures(), 1u);
    EXPECT_EQ(m.diff.width, 120);
    // A lighter green of the same hue keeps the palette but not the fidelity.
    PngImage lighter = f.native;
    const uint8_t pale[3] = {129, 224, 129};
    paint(lighter, 10, 10, 30, 30, pale);
    ASSERT_TRUE(FrameFidelity::measure(f.native, lighter, f.ids, false, m, error)) << error;
    EXPECT_TRUE(m.objects[0].hueKept);
    EXPECT_LT(m.fidelity(), 0.5);
}

TEST(FrameFidelity, TheLighterObjectStaysTheLighter)
{
    Frames f;
    const uint8_t dark[3] = {20, 60, 20}, light[3] = {200, 240, 200};
    PngImage native = f.native, styled = f.native, ids = f.ids;
    paint(native, 0, 30, 40, 40, light);
    paint(styled, 0, 30, 40, 40, dark); // the light object drawn darker than the green one
    uint8_t id[3];
    FrameFidelity::idColour(2, id);
    paint(ids, 0, 30, 40, 40, id);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(native, styled, ids, false, m, error)) << error;
    ASSERT_EQ(m.objects.size(), 2u);
    EXPECT_FALSE(m.objects[0].orderKept);
    EXPECT_FALSE(m.objects[1].orderKept);
}

TEST(FrameFidelity, TheClearColourGivenIsTheBackground)
{
    // A band over the whole border (the border's commonest colour) around a cleared inside.
    Frames f;
    const uint8_t band[3] = {140, 89, 51}, cleared[3] = {30, 30, 30};
    PngImage native = f.native;
    paint(native, 0, 0, 40, 4, band);
    paint(native, 0, 36, 40, 40, band);
    paint(native, 0, 4, 4, 36, band);
    paint(native, 36, 4, 40, 36, band);
    FrameFidelity guessed, told;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(native, native, f.ids, false, guessed, error)) << error;
    EXPECT_FALSE(guessed.clearFromStream);
    EXPECT_EQ(guessed.clear[0], band[0]);
    ASSERT_TRUE(FrameFidelity::measure(native, native, f.ids, false, told, error, PngImage(),
                                       cleared))
        << error;
    EXPECT_TRUE(told.clearFromStream);
    EXPECT_EQ(told.clear[0], cleared[0]);
    // The band is drawn; the inside around the square is not.
    EXPECT_EQ(told.nativeDrawn, 40u * 40u - 32u * 32u + 400u);
}

TEST(FrameFidelity, FramesOfDifferentSizesAreRefused)
{
    Frames f;
    FrameFidelity m;
    std::string error;
    EXPECT_FALSE(FrameFidelity::measure(f.native, filled(20, 20, 0, 0, 0), PngImage(), false, m,
                                        error));
    EXPECT_NE(error.find("size"), std::string::npos);
}

TEST(FrameFidelity, OnlyWhatTheStylesBackgroundShowsIsMissing)
{
    // The style lays a page (pale) where the program cleared (dark): a translucent panel the
    // program left is there, blended over the page, and is not missing; a square that shows
    // the page is.
    const uint8_t panel[3] = {70, 70, 90}, panelOnPage[3] = {150, 150, 160};
    const uint8_t square[3] = {200, 40, 40};
    PngImage native = filled(40, 40, 20, 20, 20);
    PngImage styled = filled(40, 40, 235, 228, 210);
    paint(native, 0, 0, 40, 8, panel);
    paint(styled, 0, 0, 40, 8, panelOnPage);
    paint(native, 20, 20, 30, 30, square);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(native, styled, filled(40, 40, 20, 20, 20), false, m,
                                       error))
        << error;
    EXPECT_EQ(m.nativeDrawn, 40u * 8u + 100u);
    EXPECT_EQ(m.missing, 100u);
}

// A faint star or a dim fringe the program drew near its black background, which a dark page
// now shows about as it was, lost nothing one can see: it is not missing. A bright one that
// shows the page is.
TEST(FrameFidelity, WhatLookedLikeThePageIsNotMissing)
{
    const uint8_t faint[3] = {34, 36, 40}, bright[3] = {200, 200, 200};
    PngImage native = filled(40, 40, 0, 0, 0);
    PngImage styled = filled(40, 40, 30, 33, 38);
    paint(native, 0, 0, 10, 10, faint);
    paint(native, 20, 20, 30, 30, bright);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(native, styled, filled(40, 40, 0, 0, 0), false, m, error))
        << error;
    EXPECT_EQ(m.nativeDrawn, 200u);
    EXPECT_EQ(m.missing, 100u) << "only the bright square is lost";
}

TEST(FrameFidelity, ASpeckAPixelApartIsRasterisationNotAnError)
{
    // Sub-pixel objects (splodesic's specks) land a pixel apart natively and restyled.
    const uint8_t white[3] = {240, 240, 240};
    PngImage native = filled(40, 40, 0, 0, 0), styled = filled(40, 40, 0, 0, 0);
    paint(native, 10, 10, 11, 11, white);
    paint(styled, 11, 10, 12, 11, white);
    FrameFidelity m;
    std::string error;
    ASSERT_TRUE(FrameFidelity::measure(native, styled, PngImage(), false, m, error)) << error;
    EXPECT_EQ(m.drawn, 1u);
    EXPECT_DOUBLE_EQ(m.fidelity(), 1.0);
    // Two pixels apart is a different picture.
    styled = filled(40, 40, 0, 0, 0);
    paint(styled, 12, 10, 13, 11, white);
    ASSERT_TRUE(FrameFidelity::measure(native, styled, PngImage(), false, m, error)) << error;
    EXPECT_DOUBLE_EQ(m.fidelity(), 0.0);
}

// Wine moves the Windows program's command line over its loader's arguments: the name glibc
// kept pointed at "" or "uild/wine/wingl64.exe" (screenshots to a missing folder, the
// per-program file ".conf"), and the command line ends in NUL padding, taken for words.
namespace {

// A w x h RGBA window of one grey, and a rectangle painted in another.
std::vector<uint8_t> window(int w, int h, uint8_t grey)
{
    std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4, grey);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    return rgba;
}

void paint(std::vector<uint8_t>& rgba, int w, int x0, int y0, int x1, int y1, uint8_t grey)
{
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            for (int c = 0; c < 3; ++c) rgba[(size_t(y) * size_t(w) + size_t(x)) * 4 + c] = grey;
        }
    }
}

} // namespace

// The draw of `before` -> `after` as `shown` shows it (its run's end).
OverlayDraw measured(const std::vector<uint8_t>& before, const std::vector<uint8_t>& after,
                     const std::vector<uint8_t>& shown, int w, int h,
                     const std::vector<uint8_t>& later = {})
{
    std::vector<uint32_t> pixels;
    OverlayLegibility::changedPixels(before.data(), after.data(), w, h, pixels);
    return OverlayLegibility::measure(pixels, shown.data(), w, h,
                                      later.empty() ? nullptr : later.data());
}

// A glyph is measured against the pixels around it, not against the whole window: a white
// glyph on a grey panel laid over black counts the panel, where the black is out of reach.
TEST(OverlayLegibility, AGlyphStandsOutFromWhatIsAroundIt)
{
    const int w = 40, h = 20;
    std::vector<uint8_t> before = window(w, h, 0);
    paint(before, w, 5, 2, 30, 17, 128); // the panel, drawn earlier
    std::vector<uint8_t> after = before;
    paint(after, w, 10, 6, 15, 13, 255); // a 6 x 8 glyph
    const OverlayDraw d = measured(before, after, after, w, h);
    EXPECT_EQ(d.pixels, 48u);
    ASSERT_TRUE(d.surrounded);
    const uint8_t white[3] = {255, 255, 255}, grey[3] = {128, 128, 128};
    const float expected = OverlayLegibility::ratio(OverlayLegibility::luminance(white),
                                                    OverlayLegibility::luminance(grey));
    EXPECT_NEAR(d.contrast, expected, 1e-3f);
    EXPECT_NEAR(expected, 3.95f, 0.01f); // WCAG: white on #808080
    // The panel itself against the black scene around it.
    const std::vector<uint8_t> black = window(w, h, 0);
    const OverlayDraw panel = measured(black, before, before, w, h);
    EXPECT_EQ(panel.pixels, 26u * 16u);
    EXPECT_NEAR(panel.contrast,
                OverlayLegibility::ratio(OverlayLegibility::luminance(grey), 0.0), 1e-3f);
}

// An antialiased glyph is judged by its strokes' cores: a fringe of pixels between glyph and
// page (a quarter of them here) does not pull its figure down.
TEST(OverlayLegibility, AnAntialiasedFringeDoesNotCountAgainstTheGlyph)
{
    const int w = 30, h = 20;
    const std::vector<uint8_t> page = window(w, h, 0);
    std::vector<uint8_t> text = page;
    paint(text, w, 9, 4, 20, 15, 60);   // the fringe, 144 pixels
    paint(text, w, 11, 5, 18, 14, 255); // the core, 80 of them
    const OverlayDraw d = measured(page, text, text, w, h);
    EXPECT_EQ(d.pixels, 144u);
    EXPECT_NEAR(d.contrast, 21.0f, 1e-3f);
}

// A shadow pass (black text under the white one, drawn first) is judged as its run shows it:
// with the white text over it, not as black on a dark page.
TEST(OverlayLegibility, AShadowIsJudgedWithTheTextDrawnOverIt)
{
    const int w = 40, h = 20;
    const std::vector<uint8_t> page = window(w, h, 40);
    std::vector<uint8_t> shadow = page;
    paint(shadow, w, 11, 7, 21, 13, 0);
    std::vector<uint8_t> text = shadow;
    paint(text, w, 10, 6, 20, 12, 255);
    // What the white pass changed is no part of the shadow's surroundings.
    std::vector<uint32_t> white;
    OverlayLegibility::changedPixels(shadow.data(), text.data(), w, h, white);
    std::vector<uint8_t> later(size_t(w) * size_t(h), 0);
    for (const uint32_t i : white) later[i] = 1;
    const OverlayDraw alone = measured(page, shadow, shadow, w, h);
    const OverlayDraw underText = measured(page, shadow, text, w, h, later);
    EXPECT_LT(alone.contrast, 1.5f) << "black on a dark page";
    const uint8_t grey[3] = {40, 40, 40};
    EXPECT_NEAR(underText.contrast, OverlayLegibility::ratio(1.0, OverlayLegibility::luminance(grey)),
                1e-3f) << "white against the page";
}

// Text in the colour of the page changes nothing: no pixels, no contrast.
TEST(OverlayLegibility, TextInThePagesColourChangesNothing)
{
    const std::vector<uint8_t> page = window(32, 16, 231);
    std::vector<uint8_t> text = page;
    paint(text, 32, 4, 4, 12, 10, 233); // within kChanged of the page
    const OverlayDraw d = measured(page, text, text, 32, 16);
    EXPECT_EQ(d.pixels, 0u);
    EXPECT_FALSE(d.surrounded);
    // Covering the whole window leaves no surroundings to judge it by.
    const std::vector<uint8_t> black = window(32, 16, 0);
    const OverlayDraw all = measured(black, page, page, 32, 16);
    EXPECT_EQ(all.pixels, 32u * 16u);
    EXPECT_FALSE(all.surrounded);
}

// A draw keeps its legibility at min(native, 4.5:1) (less 5% for antialiasing), and only
// where it is still seen.
TEST(OverlayLegibility, AStyleMustKeepTheSmallerOfNativesContrastAndAA)
{
    const std::vector<OverlayDraw> native = {
        {300, 12.0f, true}, {300, 12.0f, true}, {300, 12.0f, true}, {300, 2.0f, true},
        {300, 2.0f, true},  {10, 15.0f, true},  {5000, 1.0f, false}, {100, 6.5f, true}};
    const std::vector<OverlayDraw> styled = {
        {300, 1.3f, true},  // lost its contrast
        {20, 15.0f, true},  // drawn in the page's colour: few pixels changed
        {290, 4.4f, true},  // 4.5:1 within the slack
        {300, 1.95f, true}, // native's own low contrast, kept within the slack
        {300, 1.5f, true},  // native's low contrast, lost
        {10, 1.0f, true},   // a speck: not judged
        {5000, 1.0f, false},
        {2000, 2.1f, true}}; // shown on far more pixels than natively: gained, not lost
    const OverlayLegibility l = OverlayLegibility::judge(native, styled);
    EXPECT_TRUE(l.mismatch.empty());
    EXPECT_EQ(l.judged, 6u);
    ASSERT_EQ(l.shortOf.size(), 3u);
    EXPECT_EQ(l.shortOf[0].index, 0u);
    EXPECT_EQ(l.shortOf[1].index, 1u);
    EXPECT_FLOAT_EQ(l.shortOf[1].styled, 1.0f) << "a draw not seen has no contrast";
    EXPECT_EQ(l.shortOf[2].index, 4u);
    EXPECT_NE(l.summary().find("3 of 6 short"), std::string::npos) << l.summary();
    const OverlayLegibility differ = OverlayLegibility::judge(native, {styled[0]});
    EXPECT_FALSE(differ.mismatch.empty());
    EXPECT_EQ(differ.judged, 0u);
}

TEST(OverlayLegibility, TheReplaysLinesReadBackAndBadOnesAreRefused)
{
    const std::vector<OverlayDraw> draws = {{120, 12.41f, true}, {0, 1.0f, false}};
    const std::string text = OverlayLegibility::describe(draws);
    EXPECT_EQ(text, "2 measured: 120:12.41 0:-");
    std::vector<OverlayDraw> back;
    ASSERT_TRUE(OverlayLegibility::parse(text, back));
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].pixels, 120u);
    EXPECT_NEAR(back[0].contrast, 12.41f, 1e-4f);
    EXPECT_FALSE(back[1].surrounded);
    EXPECT_TRUE(OverlayLegibility::parse("0 measured:", back));
    EXPECT_TRUE(back.empty());
    for (const char* bad : {"", "x", "2 measured: 1:2.0", "1 measured: 5:0.5", "1 measured: 5",
                            "1 measured: 5:30", "1 measured: :2", "1 measured: 5:2 junk"}) {
        EXPECT_FALSE(OverlayLegibility::parse(bad, back)) << bad;
    }
}

TEST(ProcessName, AProgramIsNamedByItsCommandLineAsItIsNow)
{
    EXPECT_EQ(programNameFrom({"/usr/bin/glxgears"}, "glxgears"), "glxgears");
    EXPECT_EQ(programNameFrom({"build/wine/wingl64.exe", "--frames", "5"}, "wingl64.exe"),
              "wingl64.exe");
    EXPECT_EQ(programNameFrom({"C:\\Games\\Some Game\\game.exe"}, "game.exe"), "game.exe");
    EXPECT_EQ(programNameFrom({}, "comm-name"), "comm-name");
    EXPECT_EQ(programNameFrom({"dir/"}, "comm-name"), "comm-name");
}

TEST(ProcessName, TheCommandLineLosesTheNulPaddingAtItsEnd)
{
    EXPECT_EQ(trimCommandLine({"wingl.exe", "--frames", "5", "", "", ""}),
              (std::vector<std::string>{"wingl.exe", "--frames", "5"}));
    EXPECT_EQ(trimCommandLine({"prog", "", "x"}), (std::vector<std::string>{"prog", "", "x"}));
    EXPECT_EQ(processName(), "test_common");
    ASSERT_FALSE(processCommandLine().empty());
    EXPECT_FALSE(processCommandLine().back().empty());
}
