#include "shim/OverlayPanel.h"

#include "common/KeyValue.h"
#include "common/Log.h"
#include "shim/ConfigFile.h"
#include "styles/Presets.h"
#include "styles/Style.h"
#include "styles/StyleRegistry.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace nprgl {

namespace {

// The list getter ImGui::Combo takes, over a vector of names.
bool nameAt(void* data, int index, const char** out)
{
    const auto& names = *static_cast<const std::vector<std::string>*>(data);
    if (index < 0 || size_t(index) >= names.size()) return false;
    *out = names[size_t(index)].c_str();
    return true;
}

std::string hexColour(const float rgb[3])
{
    char text[8];
    std::snprintf(text, sizeof text, "%02x%02x%02x", int(std::lround(rgb[0] * 255.0f)),
                  int(std::lround(rgb[1] * 255.0f)), int(std::lround(rgb[2] * 255.0f)));
    return text;
}

// A chain as the registry reads it ("none" when empty).
std::string joinChain(const std::vector<std::string>& chain)
{
    std::string text;
    for (const std::string& s : chain)
        text += (text.empty() ? "" : "+") + s;
    return text.empty() ? "none" : text;
}

// The width of a button (or small button) labelled `label`.
float buttonWidth(const char* label)
{
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

// On the same line when an item `width` wide still fits there, else on the next: rows of
// controls wrap in a narrow window instead of running past its edge.
void sameLineIfFits(float width)
{
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

// Greyed text, wrapped at the window's edge.
void disabledWrapped(const char* text)
{
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

} // namespace

OverlayPanel::OverlayPanel(std::string programName, std::string programFile)
    : mProgramName(std::move(programName)), mProgramFile(std::move(programFile))
{
}

void OverlayPanel::follow(const StyleSettings& running)
{
    // The look changed under the panel (a reload, the cycle key, a preset): take it in.
    const std::string seen = running.chainName() + "|" + running.configText();
    if (seen == mFollowed) return;
    mFollowed = seen;
    mChain.clear();
    for (const StyleInfo* s : running.chain()) {
        if (s->create) mChain.push_back(s->name);
    }
    mValues.clear();
    mTyped.clear();
    KeyValueList pairs;
    std::string error;
    if (parseKeyValues(running.configText(), ',', pairs, error)) {
        for (auto& [key, value] : pairs)
            mValues[key] = value;
    }
    mError.clear();
    mErrorAt.clear();
}

std::string OverlayPanel::chainText() const { return joinChain(mChain); }

void OverlayPanel::setError(const std::string& at, const std::string& error)
{
    mError = error;
    mErrorAt = at;
}

void OverlayPanel::errorRow(const std::string& at) const
{
    if (mError.empty() || mErrorAt != at) return;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", mError.c_str());
    ImGui::PopTextWrapPos();
}

std::string OverlayPanel::configText() const
{
    // Only the values of styles in the chain: the registry refuses no other, but a value of a
    // removed style would come back with it unasked.
    std::string config;
    for (const auto& [key, value] : mValues) {
        const std::string style = key.substr(0, key.find('.'));
        if (std::find(mChain.begin(), mChain.end(), style) == mChain.end()) continue;
        config += (config.empty() ? "" : ",") + key + "=" + value;
    }
    return config;
}

OverlayPanel::Changes OverlayPanel::build(const StyleSettings& running, bool styled,
                                          const LeaveRules& rules, const OverlayFigures& figures)
{
    follow(running);
    Changes changes;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // At most 60% of the window's width and its height less a margin, whatever its size (and
    // as it is resized): in a small window the rows wrap and the panel scrolls.
    const ImVec2 largest(std::max(1.0f, 0.6f * display.x), std::max(1.0f, display.y - 16.0f));
    ImGui::SetNextWindowPos(ImVec2(std::min(8.0f, 0.02f * display.x), 8.0f),
                            ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::min(360.0f, largest.x), std::min(600.0f, largest.y)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), largest);
    ImGui::Begin("nprgl", nullptr, ImGuiWindowFlags_NoSavedSettings);
    if (mNoteItems) {
        const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        NPRGL_DEBUG("overlay: window at %.0f %.0f %.0f %.0f", at.x, at.y, size.x, size.y);
    }
    ImGui::TextWrapped("%s: %s", mProgramName.c_str(), chainText().c_str());
    bool on = styled;
    if (ImGui::Checkbox("styled", &on)) changes.toggle = true;
    noteItem("styled");
    char times[64];
    std::snprintf(times, sizeof times, "frame %.1f ms, nprgl %.1f ms", figures.frameMs,
                  figures.composeMs);
    sameLineIfFits(ImGui::CalcTextSize(times).x);
    ImGui::TextWrapped("%s", times);
    // The controls first, at places that do not move with the figures below them.
    changes.rules = pickRows(rules, changes.leave);
    bool edited = presetRow();
    sameLineIfFits(buttonWidth("save"));
    saveButton(changes.rules ? changes.leave : rules);
    if (!mSaved.empty()) ImGui::TextWrapped("%s", mSaved.c_str());
    errorRow("preset");
    if (figures.counts) {
        ImGui::TextWrapped("3D draws: %s", figures.counts->describe().c_str());
    }
    ImGui::Separator();
    edited = chainRows() || edited;
    for (const std::string& name : mChain) {
        const StyleInfo* style = StyleRegistry::instance().find(name);
        if (style && !style->params.empty()) edited = paramRows(*style) || edited;
    }
    ImGui::End();
    mNoteItems = false;

    if (edited) {
        std::string error;
        StyleSettings settings;
        if (StyleSettings::parse(chainText(), configText(), settings, error)) {
            mError.clear();
            mErrorAt.clear();
            mFollowed = settings.chainName() + "|" + settings.configText();
            changes.restyle = true;
            changes.settings = std::move(settings);
        } else {
            // Not reached: each edit was checked before it was made. Said at the chain.
            setError("chain", error);
        }
    }
    return changes;
}

bool OverlayPanel::presetRow()
{
    static std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Preset& p : Presets::shipped())
            n.emplace_back(p.name);
        return n;
    }();
    if (names.empty()) return false;
    ImGui::SetNextItemWidth(std::min(120.0f, ImGui::GetContentRegionAvail().x));
    ImGui::Combo("##preset", &mPreset, &nameAt, &names, int(names.size()));
    sameLineIfFits(buttonWidth("apply"));
    if (!ImGui::Button("apply")) return false;
    std::string chain, config, error;
    if (!Presets::load(names[size_t(mPreset)], chain, config, error)) {
        setError("preset", error);
        return false;
    }
    StyleSettings settings;
    if (!StyleSettings::parse(chain, config, settings, error)) {
        setError("preset", error);
        return false;
    }
    mFollowed.clear();
    follow(settings);
    NPRGL_INFO("overlay: preset %s", names[size_t(mPreset)].c_str());
    return true;
}

bool OverlayPanel::chainRows()
{
    // Every edit is a whole new chain, made only when the registry takes it: the header,
    // the running look and 'save' never see a chain it refuses.
    std::vector<std::string> next;
    std::string said;
    ImGui::TextUnformatted("chain");
    for (size_t i = 0; i < mChain.size(); ++i) {
        ImGui::PushID(int(i));
        ImGui::BulletText("%s", mChain[i].c_str());
        const ImGuiStyle& look = ImGui::GetStyle();
        const float buttons = buttonWidth("up") + buttonWidth("down") + buttonWidth("remove") +
                              2.0f * look.ItemSpacing.x;
        // In a column where the names are short enough, else after the name or below it.
        if (ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x < 150.0f - look.ItemSpacing.x &&
            ImGui::GetWindowContentRegionMax().x >= 150.0f + buttons) {
            ImGui::SameLine(150.0f);
        } else {
            sameLineIfFits(buttons);
        }
        if (ImGui::SmallButton("up") && i > 0) {
            next = mChain;
            std::swap(next[i], next[i - 1]);
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("down") && i + 1 < mChain.size()) {
            next = mChain;
            std::swap(next[i], next[i + 1]);
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("remove")) {
            next = mChain;
            next.erase(next.begin() + long(i));
            said = "removed " + mChain[i];
        }
        ImGui::PopID();
    }
    // What may be added: a style that makes a chain the registry takes. A chain takes one
    // shading style, so another one is offered in its place.
    const StyleRegistry& registry = StyleRegistry::instance();
    auto shading = std::find_if(mChain.begin(), mChain.end(), [&](const std::string& name) {
        const StyleInfo* style = registry.find(name);
        return style && style->role == styles::StyleRole::Shading;
    });
    struct Addition {
        std::string name, label;
        std::vector<std::string> chain; // the chain with it
    };
    std::vector<Addition> addable;
    for (const StyleInfo& s : registry.styles()) {
        if (!s.create || std::find(mChain.begin(), mChain.end(), s.name) != mChain.end()) {
            continue;
        }
        Addition a;
        a.name = s.name;
        a.label = s.name;
        a.chain = mChain;
        if (s.role == styles::StyleRole::Shading && shading != mChain.end()) {
            a.chain[size_t(shading - mChain.begin())] = s.name;
            a.label += " (for " + *shading + ")";
        } else {
            a.chain.push_back(s.name);
        }
        std::vector<const StyleInfo*> checked;
        std::string error;
        if (registry.parseChain(joinChain(a.chain), checked, error)) addable.push_back(a);
    }
    if (!addable.empty()) {
        mAdd = std::clamp(mAdd, 0, int(addable.size()) - 1);
        ImGui::SetNextItemWidth(std::min(140.0f, ImGui::GetContentRegionAvail().x));
        if (ImGui::BeginCombo("##add", addable[size_t(mAdd)].label.c_str())) {
            // The list's items are noted on its second frame open, when it has its final
            // layout.
            const bool noting = mNoteItems;
            mNoteItems = mNoteItems || ++mAddOpenFrames == 2;
            for (size_t i = 0; i < addable.size(); ++i) {
                if (ImGui::Selectable(addable[i].label.c_str(), int(i) == mAdd)) mAdd = int(i);
                noteItem("add " + addable[i].name);
            }
            mNoteItems = noting;
            ImGui::EndCombo();
        } else {
            mAddOpenFrames = 0;
            noteItem("add");
        }
        sameLineIfFits(buttonWidth("add style"));
        const bool add = ImGui::Button("add style");
        noteItem("add style");
        if (add) {
            const Addition& a = addable[size_t(mAdd)];
            next = a.chain;
            said = a.label == a.name ? "added " + a.name : "put " + a.label;
        }
    }
    if (next.empty() && said.empty()) {
        errorRow("chain");
        return false;
    }
    std::vector<const StyleInfo*> checked;
    std::string error;
    if (!registry.parseChain(joinChain(next), checked, error)) {
        setError("chain", error);
        errorRow("chain");
        return false;
    }
    if (!said.empty()) NPRGL_INFO("overlay: %s", said.c_str());
    mChain = std::move(next);
    mAdd = 0;
    return true;
}

bool OverlayPanel::paramRows(const StyleInfo& style)
{
    bool edited = false;
    if (!ImGui::CollapsingHeader(style.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
        return false;
    }
    ImGui::PushID(style.name.c_str());
    for (const ParamInfo& param : style.params) {
        edited = paramRow(style.name + "." + param.name, param, style) || edited;
    }
    ImGui::PopID();
    return edited;
}

double OverlayPanel::numberOf(const std::string& key, const ParamInfo& param) const
{
    double value = param.defaultValue;
    const auto it = mValues.find(key);
    if (it != mValues.end() && param.kind != ParamKind::Text && param.kind != ParamKind::Colour) {
        const ParamInfo* checked = nullptr;
        std::string error;
        if (!StyleSettings::check(key, it->second, checked, value, error))
            value = param.defaultValue;
    }
    return value;
}

void OverlayPanel::sliderRange(const StyleInfo& style, const ParamInfo& param, double& lo,
                               double& hi) const
{
    lo = param.minValue;
    hi = param.maxValue;
    for (const ParamInfo& other : style.params) {
        const std::string key = style.name + "." + other.name;
        if (!param.below.empty() && other.name == param.below)
            hi = std::min(hi, numberOf(key, other) - param.gap);
        if (other.below == param.name) lo = std::max(lo, numberOf(key, other) + other.gap);
    }
    // Values out of order (given in a file) leave no room: the slider stays where it is.
    hi = std::max(hi, lo);
}

bool OverlayPanel::paramRow(const std::string& key, const ParamInfo& param,
                            const StyleInfo& style)
{
    auto it = mValues.find(key);
    const bool configured = it != mValues.end();
    const std::string text = configured ? it->second : param.defaultString();
    // The value as the registry reads it (a choice's index, a flag's 0/1).
    const double value = numberOf(key, param);
    std::string next;
    // A control and its name on one line where both fit, else the name above the control.
    const float avail = ImGui::GetContentRegionAvail().x;
    std::string hidden;
    const char* label = param.name.c_str();
    if (avail < 160.0f + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x) {
        ImGui::TextUnformatted(label);
        hidden = "##" + param.name;
        label = hidden.c_str();
        ImGui::SetNextItemWidth(avail);
    } else {
        ImGui::SetNextItemWidth(160.0f);
    }
    switch (param.kind) {
    case ParamKind::Number:
        if (param.isFlag) {
            bool on = value != 0.0;
            if (ImGui::Checkbox(label, &on)) next = on ? "on" : "off";
        } else {
            double lo = 0.0, hi = 0.0;
            sliderRange(style, param, lo, hi);
            float v = float(value);
            const bool wide = param.minValue > 0.0 && param.maxValue / param.minValue >= 100.0;
            if (ImGui::SliderFloat(label, &v, float(lo), float(hi), "%.3g",
                                   wide ? ImGuiSliderFlags_Logarithmic : 0)) {
                next = numberText(std::clamp(double(v), lo, hi));
            }
        }
        break;
    case ParamKind::Choice: {
        int index = int(value);
        auto& choices = const_cast<std::vector<std::string>&>(param.choices);
        if (ImGui::Combo(label, &index, &nameAt, &choices, int(choices.size()))) {
            next = choices[size_t(index)];
        }
        break;
    }
    case ParamKind::Colour: {
        glm::vec3 c(1.0f);
        const bool derived = !ParamInfo::parseColour(text, c);
        float rgb[3] = {c.r, c.g, c.b};
        if (ImGui::ColorEdit3(label, rgb, ImGuiColorEditFlags_NoInputs)) next = hexColour(rgb);
        if (derived) {
            ImGui::SameLine();
            ImGui::TextDisabled("(derived)");
        }
        break;
    }
    case ParamKind::Text: {
        // A file name, typed; applied with Enter (a half-typed name would be refused).
        std::string& typed = mTyped.try_emplace(key, configured ? text : param.defaultText)
                                 .first->second;
        if (ImGui::InputText(label, &typed, ImGuiInputTextFlags_EnterReturnsTrue)) {
            next = typed;
            if (next.empty()) {
                mValues.erase(key); // back to the default
                mTyped.erase(key);
                return true;
            }
        }
        break;
    }
    }
    if (ImGui::IsItemHovered() && !param.help.empty()) ImGui::SetTooltip("%s", param.help.c_str());
    noteItem(key);
    bool changed = !next.empty() && next != text;
    if (changed) {
        // Checked with the rest of the look before it is taken (a typed file name may hold
        // the ',' that separates values).
        mValues[key] = next;
        StyleSettings settings;
        std::string error;
        if (!StyleSettings::parse(chainText(), configText(), settings, error)) {
            if (configured) {
                mValues[key] = text;
            } else {
                mValues.erase(key);
            }
            setError(key, error);
            changed = false;
        }
    }
    // One line per edit: a slider says its value when let go, not at every frame of the drag.
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        NPRGL_INFO("overlay: %s=%s", key.c_str(), mValues.count(key) ? mValues[key].c_str() : "");
    }
    errorRow(key);
    return changed;
}

void OverlayPanel::picked(const PickResult& hit, uint64_t textureHash)
{
    mPickedHash = hit.hit ? textureHash : 0;
    mPickedStates = hit.hit ? hit.states : 0;
    // The states first: the line is cut at the panel's edge, and a hash is long.
    const std::string states = mPickedStates ? LeaveRules::stateNames(mPickedStates) + ", " : "";
    char text[200];
    if (!hit.hit) {
        std::snprintf(text, sizeof text, "nothing nprgl styles there");
    } else if (hit.texture == 0) {
        std::snprintf(text, sizeof text, "object %u (%u faces), %suntextured", hit.object,
                      hit.faces, states.c_str());
    } else if (textureHash == 0) {
        std::snprintf(text, sizeof text,
                      "object %u (%u faces), %stexture %u: its content was not seen uploaded",
                      hit.object, hit.faces, states.c_str(), hit.texture);
    } else {
        std::snprintf(text, sizeof text, "object %u (%u faces), %stexture %u = %s", hit.object,
                      hit.faces, states.c_str(), hit.texture,
                      ConfigFile::hashText(textureHash).c_str());
    }
    mPick = text;
    NPRGL_INFO("overlay: picked %s", text);
}

bool OverlayPanel::pickRows(const LeaveRules& rules, LeaveRules& next)
{
    ImGui::Checkbox("pick", &mPicking);
    noteItem("pick");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("then click an object of the program");
    bool changed = false;
    // A button that edits the rules, disabled where it would change nothing.
    auto ruleButton = [&](const char* label, bool enabled, auto edit) {
        sameLineIfFits(buttonWidth(label));
        ImGui::BeginDisabled(!enabled);
        if (ImGui::Button(label)) {
            next = rules;
            edit(next);
            changed = true;
        }
        noteItem(label);
        ImGui::EndDisabled();
    };
    const bool textureLeft = rules.leavesTexture(mPickedHash);
    ruleButton("leave texture", mPickedHash != 0 && !textureLeft, [&](LeaveRules& r) {
        r.textures.push_back(mPickedHash);
        r.normalise();
        NPRGL_INFO("overlay: rule: leave texture %s", ConfigFile::hashText(mPickedHash).c_str());
    });
    ruleButton("style texture", textureLeft, [&](LeaveRules& r) {
        std::erase(r.textures, mPickedHash);
        NPRGL_INFO("overlay: rule: style texture %s", ConfigFile::hashText(mPickedHash).c_str());
    });
    char count[32];
    std::snprintf(count, sizeof count, "%zu rule%s", rules.count(), rules.count() == 1 ? "" : "s");
    sameLineIfFits(ImGui::CalcTextSize(count).x);
    ImGui::TextDisabled("%s", count);
    // A state rule leaves every draw in any of the picked object's states (for a translucent
    // decal: every translucent draw and every decal), as leave_state lines do.
    const std::string names = LeaveRules::stateNames(mPickedStates, " or ");
    ruleButton("leave state", (mPickedStates & ~rules.states) != 0, [&](LeaveRules& r) {
        r.states |= mPickedStates;
        NPRGL_INFO("overlay: rule: leave state %s", names.c_str());
    });
    if (mPickedStates && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
        ImGui::SetTooltip("leave every draw that is %s as the program draws it", names.c_str());
    }
    ruleButton("style state", (mPickedStates & rules.states) != 0, [&](LeaveRules& r) {
        r.states &= ~mPickedStates;
        NPRGL_INFO("overlay: rule: style state %s", names.c_str());
    });
    const std::string left =
        "left: " + (rules.states ? LeaveRules::stateNames(rules.states) : std::string("none"));
    sameLineIfFits(ImGui::CalcTextSize(left.c_str()).x);
    ImGui::TextDisabled("%s", left.c_str());
    // Always there: the rows below keep their places (the tests click them).
    disabledWrapped(mPick.empty() ? "pick, then click an object: rules by its texture or its "
                                    "state"
                                  : mPick.c_str());
    return changed;
}

void OverlayPanel::saveButton(const LeaveRules& rules)
{
    if (mProgramFile.empty()) {
        ImGui::TextDisabled("(no config folder)");
        return;
    }
    const bool clicked = ImGui::Button("save");
    noteItem("save");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("write this look to %s", mProgramFile.c_str());
    if (!clicked) return;
    std::string error;
    if (ConfigFile::writeLook(mProgramFile, chainText(), configText(), rules, error)) {
        mSaved = "saved to " + mProgramFile;
        NPRGL_INFO("overlay: %s: style=%s %s", mSaved.c_str(), chainText().c_str(),
                   configText().c_str());
    } else {
        mSaved = error;
        NPRGL_ERROR("overlay: %s", error.c_str());
    }
}

void OverlayPanel::noteItem(const std::string& id) const
{
    if (!mNoteItems) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    NPRGL_DEBUG("overlay: item %s at %.0f %.0f %.0f %.0f", id.c_str(), lo.x, lo.y, hi.x - lo.x,
                hi.y - lo.y);
}

void OverlayPanel::noteLayout() { mNoteItems = true; }

} // namespace nprgl
