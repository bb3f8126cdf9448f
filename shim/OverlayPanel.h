#pragma once

// OverlayPanel: the overlay's window: chain, parameters, presets, coverage and frame times.

#include "frame/DrawCounts.h"
#include "frame/LeaveRules.h"
#include "frame/ScenePick.h"
#include "styles/StyleSettings.h"

#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace nprgl {

// What the panel shows of the running program.
struct OverlayFigures {
    const DrawCounts* counts = nullptr; // the last frame's 3D draws, styled and left
    double frameMs = 0.0;               // from swap to swap
    double composeMs = 0.0;             // of which nprgl's compositor (reconstruction, styles)
};

// Builds the ImGui widgets of one frame (an ImGui frame must be open) from the look the
// compositor runs, and says what the user changed. Every edit is checked (StyleSettings, the
// registry) before it is made: a refused one changes nothing, and its message shows under the
// control that made it. The add list offers only styles that make a chain the registry takes
// (a second shading style is offered in place of the chain's).
class OverlayPanel {
public:
    // `programFile`: where "save" writes (the per-program configuration file).
    OverlayPanel(std::string programName, std::string programFile);

    struct Changes {
        bool restyle = false; // run `settings` from the next frame
        StyleSettings settings;
        bool toggle = false; // styling on/off
        bool rules = false;  // run `leave` from the next frame
        LeaveRules leave;
    };
    // `rules`: the rules the compositor runs.
    Changes build(const StyleSettings& running, bool styled, const LeaveRules& rules,
                  const OverlayFigures& figures);
    // Pick mode is on: the next click off the panel picks the object under it.
    bool picking() const { return mPicking; }
    // What the click picked (an object or none), its face's texture's content hash.
    void picked(const PickResult& hit, uint64_t textureHash);
    // The next build() logs its items' rectangles (at debug level).
    void noteLayout();

private:
    void follow(const StyleSettings& running);
    bool chainRows();
    bool presetRow();
    bool paramRows(const StyleInfo& style);
    bool paramRow(const std::string& key, const ParamInfo& param, const StyleInfo& style);
    // A number's value as the registry reads it: configured, else its default.
    double numberOf(const std::string& key, const ParamInfo& param) const;
    // The range a number's slider offers: its own, narrowed by the numbers the style keeps
    // it below or above (ParamInfo::below), so the value shown is the value the style runs.
    void sliderRange(const StyleInfo& style, const ParamInfo& param, double& lo,
                     double& hi) const;
    void saveButton(const LeaveRules& rules);
    bool pickRows(const LeaveRules& rules, LeaveRules& next);
    // With noteLayout(): logs (debug) where an item is, for tests that click it with XTEST.
    void noteItem(const std::string& id) const;
    std::string chainText() const;
    // An edit refused: the message shows under the control `at` ("preset", "chain", a
    // "style.param") until the next accepted edit.
    void setError(const std::string& at, const std::string& error);
    void errorRow(const std::string& at) const;
    std::string configText() const;

    std::string mProgramName;
    std::string mProgramFile;
    std::vector<std::string> mChain;            // style names, in order
    std::map<std::string, std::string> mValues; // "style.param" -> text, defaults left out
    std::map<std::string, std::string> mTyped;  // text parameters as typed so far
    std::string mFollowed;                      // the running look last taken in
    std::string mError;                         // the registry's answer to the last edit
    std::string mErrorAt;                       // the control it is shown at
    std::string mSaved;                         // the last save's outcome
    int mAdd = 0;                               // the style chosen to add
    int mAddOpenFrames = 0;                     // how long its list has been open
    int mPreset = 0;                            // the preset chosen to apply
    bool mNoteItems = false;
    bool mPicking = false;
    std::string mPick;        // what the last pick found, as shown
    uint64_t mPickedHash = 0; // its texture's content hash (0: untextured or unknown)
    uint32_t mPickedStates = 0; // the states it was drawn in (LeftState bits)
};

} // namespace nprgl
