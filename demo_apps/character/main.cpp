// demo_character: the three character-animation techniques on models from assimp-testmodels:
// morphing between MD2 keyframes, linear-blend skinning of a boned mesh, and rigid limbs
// driven by a BVH motion clip. The geometry goes to GL every frame through client arrays,
// immediate mode (--immediate) or buffer objects (--vbo). --rss-every N prints the process's
// resident memory every N frames to stderr, for soak benchmarks (bench/soak.py).

#include "Demo.h"
#include "Md2Animator.h"
#include "MeshDrawer.h"
#include "RigidAnimator.h"
#include "SkinAnimator.h"

#include <GL/gl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <memory>
#include <numbers>

namespace {

constexpr const char* defaultModel = "/usr/share/assimp/models/MD2/sydney.md2";
constexpr double animationStep = 1.0 / 30.0; // seconds of animation per frame, never wall time
constexpr float orbitDegreesPerFrame = 1.0f;
constexpr float elevationDegrees = 12.0f;
constexpr double fieldOfView = 35.0;

std::string lowerExtension(const std::string& path)
{
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

class CharacterScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        using Kind = demo::ExtraOption::Kind;
        return {{"model", Kind::Text, std::string("model file (default ") + defaultModel + ")"},
                {"technique", Kind::Text, "morph, skin or rigid (default: from the file type)"},
                {"clip", Kind::Text, "animation or MD2 frame group to play"},
                {"texture", Kind::Text, "MD2 skin (BMP; default: the one beside the model)"},
                {"immediate", Kind::Flag, "draw in immediate mode"},
                {"vbo", Kind::Flag, "draw from buffer objects refilled every frame"},
                {"rss-every", Kind::Int, "print VmRSS to stderr every N frames"}};
    }

    bool init(const demo::Options& options, std::string& error) override
    {
        rssEvery_ = options.intValue("rss-every", 0);
        std::string path = options.textValue("model", defaultModel);
        if (!std::ifstream(path, std::ios::binary)) {
            error = "cannot open model file " + path;
            return false;
        }
        std::string technique = options.textValue("technique", "");
        if (technique.empty()) {
            std::string ext = lowerExtension(path);
            technique = ext == ".md2" ? "morph" : (ext == ".bvh" ? "rigid" : "skin");
        }
        if (technique == "morph") {
            auto md2 = std::make_unique<character::Md2Animator>();
            md2->setSkinPath(options.textValue("texture", ""));
            animator_ = std::move(md2);
        } else if (technique == "skin") {
            animator_ = std::make_unique<character::SkinAnimator>();
        } else if (technique == "rigid") {
            animator_ = std::make_unique<character::RigidAnimator>();
        } else {
            error = "unknown technique " + technique + " (morph, skin or rigid)";
            return false;
        }
        if (!animator_->load(path, options.textValue("clip", ""), error)) return false;
        if (options.report) std::printf("%s\n", animator_->describe().c_str());

        using Mode = character::MeshDrawer::Mode;
        drawer_ = std::make_unique<character::MeshDrawer>(
            options.has("vbo") ? Mode::BufferObjects
                               : (options.has("immediate") ? Mode::Immediate : Mode::ClientArrays));
        frameModel();

        glViewport(0, 0, options.width, options.height);
        distance_ = static_cast<float>(1.05 / std::sin(fieldOfView * std::numbers::pi / 360.0));
        demo::setPerspective(fieldOfView, static_cast<double>(options.width) / options.height,
                             0.05 * distance_, distance_ + 4.0);
        glClearColor(0.12f, 0.13f, 0.16f, 1.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE); // the framing scale shortens the normals
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        // A textured model takes its colours from the texture (modulated by white light).
        const bool textured = animator_->skin() != nullptr;
        const float ambient[] = {0.25f, 0.2f, 0.18f, 1.0f};
        const float diffuse[] = {textured ? 1.0f : 0.85f, textured ? 1.0f : 0.62f,
                                 textured ? 1.0f : 0.45f, 1.0f};
        const float specular[] = {0.3f, 0.3f, 0.3f, 1.0f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
        glShadeModel(GL_SMOOTH);
        drawer_->init(animator_->skin());
        return true;
    }

    void draw(int frame) override
    {
        animator_->pose((frame - 1) * animationStep, pose_);

        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        const float lightDirection[] = {0.4f, 0.8f, 0.7f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glTranslatef(0.0f, 0.0f, -distance_);
        glRotatef(elevationDegrees, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * orbitDegreesPerFrame, 0.0f, 1.0f, 0.0f);
        glScalef(1.0f / radius_, 1.0f / radius_, 1.0f / radius_);
        glTranslatef(-centre_[0], -centre_[1], -centre_[2]);
        drawer_->draw(pose_);
        if (rssEvery_ > 0 && frame % rssEvery_ == 0) printResidentMemory(frame);
    }

    void shutdown() override
    {
        if (drawer_) drawer_->shutdown();
    }

private:
    // "demo_character: frame=N vmrss_kib=K", K from /proc/self/status (0 if not found). By
    // frame number, not by time, so that samples of different runs line up.
    static void printResidentMemory(int frame)
    {
        long kib = 0;
        std::ifstream status("/proc/self/status");
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("VmRSS:", 0) == 0) {
                kib = std::strtol(line.c_str() + 6, nullptr, 10);
                break;
            }
        }
        std::fprintf(stderr, "demo_character: frame=%d vmrss_kib=%ld\n", frame, kib);
    }

    // Centre and radius of the first pose, with every part in its place.
    void frameModel()
    {
        animator_->pose(0.0, pose_);
        float low[3] = {1e30f, 1e30f, 1e30f}, high[3] = {-1e30f, -1e30f, -1e30f};
        for (const character::Part& part : pose_.parts) {
            const float* m = part.matrix;
            for (uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i) {
                const float* p = pose_.vertices[pose_.indices[i]].position;
                for (int k = 0; k < 3; ++k) {
                    float v = m[k] * p[0] + m[4 + k] * p[1] + m[8 + k] * p[2] + m[12 + k];
                    low[k] = std::min(low[k], v);
                    high[k] = std::max(high[k], v);
                }
            }
        }
        float squared = 0.0f;
        for (int k = 0; k < 3; ++k) {
            centre_[k] = 0.5f * (low[k] + high[k]);
            squared += 0.25f * (high[k] - low[k]) * (high[k] - low[k]);
        }
        radius_ = squared > 0.0f ? std::sqrt(squared) : 1.0f;
    }

    std::unique_ptr<character::Animator> animator_;
    std::unique_ptr<character::MeshDrawer> drawer_;
    character::CharacterPose pose_;
    float centre_[3] = {0.0f, 0.0f, 0.0f};
    float radius_ = 1.0f;
    float distance_ = 5.0f;
    int rssEvery_ = 0;
};

} // namespace

int main(int argc, char** argv)
{
    CharacterScene scene;
    return demo::run(argc, argv, "character", scene);
}
