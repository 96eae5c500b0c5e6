// One render request for every front end: each bad request of tests/data/bad_render_requests.json is refused by
// the command line and by a viewer script's render action with the field and the reason render::check() gives,
// each in its own words (--time-limit, actions[0].timeLimit); the valid controls pass both. Python is held to
// the same table by tests/python/test_request_limits.py.
#include "app/script.h"
#include "cli_run.h"
#include "render/render_request.h"
#include "util/input_error.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>

using namespace shadelab;
using nlohmann::json;

namespace {

json cases() {
    std::ifstream in(test::sourcePath("tests/data/bad_render_requests.json"));
    return json::parse(in).at("cases");
}

render::RenderRequest requestOf(const json& c) {
    render::RenderRequest r;
    if (c.contains("renderer")) r.engine = *lookupName(render::kEngineNames, c["renderer"].get<std::string>());
    if (c.contains("size")) r.width = c["size"][0], r.height = c["size"][1];
    if (c.contains("spp")) r.spp = c["spp"].get<int>();
    if (c.contains("depth")) r.depth = c["depth"].get<int>();
    if (c.contains("threads")) r.threads = c["threads"];
    if (c.contains("time_limit")) r.path.timeLimit = c["time_limit"].get<double>();
    if (c.contains("estimator"))
        r.path.estimator = *lookupName(trace::kPathEstimatorNames, c["estimator"].get<std::string>());
    if (c.contains("light_paths"))
        r.path.part = *lookupName(trace::kPathPartNames, c["light_paths"].get<std::string>());
    if (c.contains("sampler")) r.path.sampler = *lookupName(trace::kPathSamplerNames, c["sampler"].get<std::string>());
    if (c.contains("exposure")) r.exposure = c["exposure"].get<double>();
    if (c.contains("view_transform"))
        r.viewTransform = *lookupName(kViewTransformNames, c["view_transform"].get<std::string>());
    return r;
}

// The command line's flags for a case: each key as --key-with-dashes, a size as WxH.
std::string flagsOf(const json& c) {
    std::string flags;
    for (const auto& [key, value] : c.items()) {
        if (key == "what" || key == "field") continue;
        std::string flag = "--" + key;
        std::replace(flag.begin(), flag.end(), '_', '-');
        const std::string v = key == "size"
                                  ? std::to_string(value[0].get<int>()) + "x" + std::to_string(value[1].get<int>())
                              : value.is_string() ? value.get<std::string>()
                                                  : value.dump();
        flags += " " + flag + " " + v;
    }
    return flags;
}

// A script's key for a request field: camelCase ("time_limit" -> "timeLimit").
std::string camelCase(const std::string& field) {
    std::string key;
    for (size_t i = 0; i < field.size(); ++i)
        key += field[i] == '_' ? char(std::toupper(static_cast<unsigned char>(field[++i]))) : field[i];
    return key;
}

// A script of one render action with the case's keys.
std::string scriptOf(const json& c) {
    json action = {{"action", "render"}, {"path", test::outputPath("frontends_unused.png")}};
    for (const auto& [key, value] : c.items())
        if (key != "what" && key != "field") action[camelCase(key)] = value;
    return json{{"actions", json::array({action})}}.dump();
}

}  // namespace

TEST(RenderRequestFrontEnds, TheTableStatesEachCasesField) {
    for (const json& c : cases()) {
        const std::optional<render::RequestProblem> p = render::check(requestOf(c));
        const std::string expected = c["field"].is_null() ? "" : c["field"].get<std::string>();
        EXPECT_EQ(p ? p->field : "", expected) << c["what"];
    }
}

TEST(RenderRequestFrontEnds, TheCommandLineNamesTheFlagAndGivesTheReason) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string out = test::outputPath("frontends.png");
    for (const json& c : cases()) {
        const test::Result r = test::run("render " + scene + " -o " + out + flagsOf(c));
        const std::optional<render::RequestProblem> p = render::check(requestOf(c));
        if (!p) {
            EXPECT_EQ(r.code, 0) << c["what"] << ": " << r.out;  // the control renders
            continue;
        }
        std::string flag = "--" + p->field;
        std::replace(flag.begin(), flag.end(), '_', '-');
        EXPECT_EQ(r.code, 2) << c["what"] << ": " << r.out;
        EXPECT_NE(r.out.find(flag + ": " + p->reason), std::string::npos)
            << c["what"] << ": expected '" << flag << ": " << p->reason << "' in: " << r.out;
    }
}

TEST(RenderRequestFrontEnds, AScriptNamesTheKeyAndGivesTheReason) {
    for (const json& c : cases()) {
        const std::optional<render::RequestProblem> p = render::check(requestOf(c));
        const std::string text = scriptOf(c);
        if (!p) {
            EXPECT_NO_THROW(app::parseScript(text, "actions.json")) << c["what"];  // the control parses
            continue;
        }
        try {
            app::parseScript(text, "actions.json");
            ADD_FAILURE() << c["what"] << ": the script was accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), "actions.json: actions[0]." + camelCase(p->field) + ": " + p->reason)
                << c["what"];
        }
    }
}
