#include "styles/PageTone.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

namespace {

float linear(float c)
{
    c = std::clamp(c, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

float PageTone::luminance(glm::vec3 c)
{
    return 0.2126f * linear(c.r) + 0.7152f * linear(c.g) + 0.0722f * linear(c.b);
}

void PageTone::observe(uint64_t frame, glm::vec3 clear)
{
    if (mMode != Mode::Auto || frame == mFrame) return;
    mFrame = frame;
    const float y = luminance(clear);
    if (!mDecided) {
        mDecided = true;
        mDark = y < 0.5f * (kDarkBelow + kLightAbove);
        return;
    }
    const bool other = mDark ? y > kLightAbove : y < kDarkBelow;
    mOther = other ? mOther + 1 : 0;
    if (mOther >= kHoldFrames) {
        mDark = !mDark;
        mOther = 0;
    }
}

glm::vec3 PageTone::ink(glm::vec3 configured) const
{
    if (!mDark) return configured;
    // Lift a dark ink by the same amount on every channel (its hue stays) to a chalk of
    // luminance about 0.75; a light ink is light already.
    const float y = luminance(configured);
    if (y >= 0.5f) return configured;
    const float lift = 0.88f - std::max({configured.r, configured.g, configured.b}) * 0.5f;
    return glm::clamp(configured + glm::vec3(std::max(lift, 0.0f)), 0.0f, 1.0f);
}

glm::vec3 PageTone::line(glm::vec3 configured, float lightness) const
{
    const float t = std::clamp(lightness, 0.0f, 1.0f);
    return glm::mix(ink(configured), mDark ? glm::vec3(0.0f) : glm::vec3(1.0f), t);
}

} // namespace nprgl::styles
