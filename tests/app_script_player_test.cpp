// ScriptPlayer (app/script_player.h): a viewer script played frame by frame against a window that only records
// what it is asked, so waits, timeouts and drags are tested without one.
#include "app/script_player.h"
#include "app_test_util.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::app;
using namespace shadelab::test;

namespace {

class RecordingWindow : public ScriptWindow {
public:
    void perform(const ScriptAction& action) override { performed.push_back(action.name); }
    bool referenceComplete() override { return referenceDone; }
    bool writeSmoothFrame(const std::string& path) override {
        if (smoothReady) written.push_back(path);
        return smoothReady;
    }
    double seconds() override { return clock; }

    std::vector<std::string> performed, written;
    bool referenceDone = false, smoothReady = false;
    double clock = 0.0;
};

ScriptPlayer player(const std::string& text) { return ScriptPlayer(parseScript(text, "lesson.json")); }

std::string errorOf(ScriptPlayer& p, int frame, ViewerState& state, ScriptWindow& window) {
    try {
        p.play(frame, state, window);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST(ScriptPlayer, StateActionsApplyAtTheirFrameAndWindowActionsGoToTheWindow) {
    ScriptPlayer p = player(R"([
        {"action": "setShininess", "object": "gold", "s": 128},
        {"frame": 2, "action": "screenshot", "path": "a.png"},
        {"frame": 2, "action": "setTerm", "term": "specular", "on": false}
    ])");
    ViewerState state = defaultState();
    RecordingWindow window;
    p.play(0, state, window);
    EXPECT_EQ(state.scene.spheres[idOf(state, "gold") - 1].material.s, 128.0f);
    EXPECT_TRUE(state.scene.terms.specular);  // control: its frame has not come
    EXPECT_TRUE(window.performed.empty());
    EXPECT_FALSE(p.finished());
    p.play(1, state, window);
    EXPECT_TRUE(window.performed.empty());
    p.play(2, state, window);
    EXPECT_EQ(window.performed, std::vector<std::string>{"screenshot"});
    EXPECT_FALSE(state.scene.terms.specular);
    EXPECT_TRUE(p.finished());
}

TEST(ScriptPlayer, WaitReferenceHoldsTheScriptUntilTheReferenceIsCompleteOrItsTimeoutPasses) {
    const std::string text = R"([
        {"action": "waitReference", "timeout": 10},
        {"action": "referenceScreenshot", "path": "ref.png"}
    ])";
    ViewerState state = defaultState();
    RecordingWindow window;
    ScriptPlayer p = player(text);
    p.play(0, state, window);
    EXPECT_TRUE(p.waitingForReference());
    window.clock = 9.0;
    p.play(1, state, window);
    EXPECT_TRUE(window.performed.empty());  // held: the screenshot waits
    window.referenceDone = true;
    p.play(2, state, window);
    EXPECT_FALSE(p.waitingForReference());
    EXPECT_EQ(window.performed, std::vector<std::string>{"referenceScreenshot"});
    EXPECT_TRUE(p.finished());

    ScriptPlayer late = player(text);
    RecordingWindow slow;
    late.play(0, state, slow);
    slow.clock = 10.5;
    EXPECT_EQ(errorOf(late, 1, state, slow), "lesson.json: actions[0]: the reference did not finish within 10 s");
    EXPECT_TRUE(slow.performed.empty());
}

TEST(ScriptPlayer, ASmoothScreenshotIsWrittenOnceTheSmoothFrameHasConverged) {
    ScriptPlayer p = player(R"([{"action": "smoothScreenshot", "path": "smooth.png", "timeout": 5},
                               {"action": "screenshot", "path": "after.png"}])");
    ViewerState state = defaultState();
    RecordingWindow window;
    p.play(0, state, window);
    p.play(1, state, window);
    EXPECT_TRUE(window.written.empty());
    EXPECT_FALSE(p.finished());
    window.smoothReady = true;
    p.play(2, state, window);
    EXPECT_EQ(window.written, std::vector<std::string>{"smooth.png"});
    EXPECT_EQ(window.performed, std::vector<std::string>{"screenshot"});

    ScriptPlayer never = player(R"([{"action": "smoothScreenshot", "path": "smooth.png", "timeout": 5}])");
    RecordingWindow still;
    never.play(0, state, still);
    still.clock = 6.0;
    EXPECT_NE(errorOf(never, 1, state, still).find("actions[0]: the smooth frame did not complete within 5 s"),
              std::string::npos);
}

TEST(ScriptPlayer, ADragMovesPressesStepsAndReleasesThenTheScriptGoesOn) {
    ScriptPlayer p = player(R"([{"action": "drag", "x0": 10, "y0": 20, "x1": 50, "y1": 20, "steps": 4},
                               {"action": "screenshot", "path": "after.png"}])");
    ViewerState state = defaultState();
    RecordingWindow window;
    EXPECT_FALSE(p.nextDragPointer());  // control: no drag yet
    p.play(0, state, window);
    std::vector<DragPointer> pointers;
    for (int frame = 1; frame < 20; ++frame) {
        p.play(frame, state, window);
        if (!window.performed.empty()) break;
        const auto pointer = p.nextDragPointer();
        ASSERT_TRUE(pointer) << frame;
        pointers.push_back(*pointer);
    }
    // Move to the start, press, four moves (the last at the end point, still pressed), then the release, held
    // for two frames.
    ASSERT_EQ(pointers.size(), 8u);
    EXPECT_FALSE(pointers[0].down);
    EXPECT_EQ(pointers[0].imagePixel, glm::vec2(10.5f, 20.5f));
    EXPECT_TRUE(pointers[1].down);
    EXPECT_EQ(pointers[1].imagePixel, glm::vec2(10.5f, 20.5f));
    EXPECT_TRUE(pointers[5].down);
    EXPECT_EQ(pointers[5].imagePixel, glm::vec2(50.5f, 20.5f));
    EXPECT_FALSE(pointers[6].down);
    EXPECT_FALSE(pointers[7].down);
    EXPECT_EQ(window.performed, std::vector<std::string>{"screenshot"});
    EXPECT_TRUE(p.finished());
}

TEST(ScriptPlayer, AFailureNamesTheScriptTheActionAndItsField) {
    ScriptPlayer p = player(R"([{"action": "screenshot", "path": "a.png"}])");
    const ScriptAction action = parseScript(R"([{"action": "screenshot", "path": "a.png"}])", "x").actions[0];
    try {
        p.fail(action, "no room", "path");
        FAIL() << "fail() returned";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "lesson.json: actions[0].path: no room");
    }
}
