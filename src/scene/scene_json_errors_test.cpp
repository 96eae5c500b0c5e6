// Scene JSON validation (docs/scene-format.md, "Errors"): one case per rule, each error naming the file, the JSON path
// and the reason in one line (e.g. "lights[2].color: expected 3 numbers, got 2").
#include "scene/scene_json.h"

#include "util/input_error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shadelab {
namespace {

Scene parse(const std::string& text) { return parseSceneJson(text, "a.json"); }

// ---- Errors: each names the file, the JSON path and the reason -------------------------------------------

struct ErrorCase {
    const char* place;   // expected JSON path or "line L, column C"
    const char* reason;  // expected substring of the reason
};

std::string lightsJson(int n) {
    std::string s = R"({"lights": [)";
    for (int i = 0; i < n; ++i) s += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 0]})";
    return s + "]}";
}

TEST(SceneJson, ErrorsNameThePathAndTheReason) {
    const std::string sphere = R"({"objects": [{"type": "sphere", "center": [0, 1, 0], "radius": 1, )";
    const std::string plane = R"({"objects": [{"type": "plane", )";
    const std::string mesh = R"({"objects": [{"type": "mesh", "source": "m.glb", )";
    const std::string ball = R"({"objects": [{"type": "sphere", )";
    const std::string light = R"({"lights": [{"type": "point", "position": [0, 1, 0], )";
    const std::string spot = R"({"lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], )";
    const std::string dirLight = R"({"lights": [{"type": "directional", "direction": [0, -1, 0], )";
    std::string threeLights = R"({"lights": [{"type": "point", "position": [0, 1, 0]},
        {"type": "directional", "direction": [0, -1, 0]}, {"type": "point", "position": [0, 1, 0], "color": [1, 1]}]})";
    std::string tooMany = lightsJson(kMaxLights + 1);
    std::string m = sphere + R"("material": )";
    std::vector<std::pair<std::string, ErrorCase>> cases = {
        {threeLights, {"lights[2].color", "expected 3 numbers, got 2"}},
        {m + R"({"s": "high"}}]})", {"objects[0].material.s", "expected a number, got string"}},
        {m + R"({"s": 20000}}]})", {"objects[0].material.s", "must be in [0, 10000]"}},
        {m + R"({"s": -1}}]})", {"objects[0].material.s", "must be in [0, 10000]"}},
        {m + R"({"ior": 0}}]})", {"objects[0].material.ior", "must be > 0"}},
        {m + R"({"baseColor": [0.5, 1.5, 0]}}]})", {"objects[0].material.baseColor[1]", "must be in [0, 1]"}},
        {m + R"({"metallic": -0.1}}]})", {"objects[0].material.metallic", "must be in [0, 1]"}},
        {m + R"({"roughness": 2}}]})", {"objects[0].material.roughness", "must be in [0, 1]"}},
        {m + R"({"disney": {"sheen": 1.5}}}]})", {"objects[0].material.disney.sheen", "must be in [0, 1]"}},
        {m + R"({"disney": 0.5}}]})", {"objects[0].material.disney", "expected an object, got number"}},
        {m + R"({"clearcoat": {"factor": 1.5}}}]})", {"objects[0].material.clearcoat.factor", "must be in [0, 1]"}},
        {m + R"({"clearcoat": {"roughness": -0.5}}}]})",
         {"objects[0].material.clearcoat.roughness", "must be in [0, 1]"}},
        {m + R"({"clearcoat": [1, 0]}}]})", {"objects[0].material.clearcoat", "expected an object, got array"}},
        {m + R"({"specular": {"factor": 2}}}]})", {"objects[0].material.specular.factor", "must be in [0, 1]"}},
        {m + R"({"sheen": {"color": [1, 1.5, 1]}}}]})", {"objects[0].material.sheen.color[1]", "must be in [0, 1]"}},
        {m + R"({"sheen": {"roughness": -0.5}}}]})", {"objects[0].material.sheen.roughness", "must be in [0, 1]"}},
        {m + R"({"sheen": 1}}]})", {"objects[0].material.sheen", "expected an object"}},
        {m + R"({"anisotropy": {"strength": 1.5}}}]})",
         {"objects[0].material.anisotropy.strength", "must be in [0, 1]"}},
        {m + R"({"anisotropy": {"rotation": 1e9}}}]})", {"objects[0].material.anisotropy.rotation", "must be in"}},
        {m + R"({"transmission": {"factor": -0.5}}}]})",
         {"objects[0].material.transmission.factor", "must be in [0, 1]"}},
        {m + R"({"volume": {"thickness": -1}}}]})", {"objects[0].material.volume.thickness", "must be in"}},
        {m + R"({"volume": {"attenuationDistance": 0}}}]})",
         {"objects[0].material.volume.attenuationDistance", "must be in"}},
        {m + R"({"volume": {"attenuationColor": [2, 0, 0]}}}]})",
         {"objects[0].material.volume.attenuationColor[0]", "must be in"}},
        {m + R"({"specular": {"color": [1, -1, 1]}}}]})", {"objects[0].material.specular.color[1]", "must be >= 0"}},
        {m + R"({"model": "principled"}}]})", {"objects[0].material.model", "disney"}},
        {m + R"({"ms": -0.5}}]})", {"objects[0].material.ms", "must be >= 0"}},
        {m + R"({"kr": [0.5, -1, 0]}}]})", {"objects[0].material.kr[1]", "must be >= 0"}},
        {m + R"({"md": [1, 1, 1, 1]}}]})", {"objects[0].material.md", "expected 3 numbers, got 4"}},
        {m + R"("golld"}]})", {"objects[0].material", "unknown material 'golld'"}},
        {m + R"(7}]})", {"objects[0].material", "expected an object, got number"}},
        {R"({"camera": {"fovY": 180}})", {"camera.fovY", "must be in (0, 180)"}},
        {R"({"environment": {"hdr": ""}})", {"environment.hdr", "must name a .hdr file"}},
        {R"({"environment": {"hdr": 3}})", {"environment.hdr", "expected a string"}},
        {R"({"environment": {"intensity": -1}})", {"environment.intensity", "must be >= 0"}},
        {R"({"environment": {"rotation": 400}})", {"environment.rotation", "must be in [-360, 360]"}},
        {R"({"environment": "sky.hdr"})", {"environment", "expected an object, got string"}},
        {R"({"energyCompensation": 1})", {"energyCompensation", "expected"}},
        {R"({"camera": {"fovY": 0}})", {"camera.fovY", "must be in (0, 180)"}},
        {R"({"camera": {"fovY": 1e39}})", {"camera.fovY", "must be finite"}},
        {R"({"camera": {"position": [0, "a", 0]}})", {"camera.position[1]", "expected a number, got string"}},
        {R"({"camera": {"position": [0, 0.5, 0]}})", {"camera.target", "must differ from camera.position"}},
        {R"({"camera": {"position": [0, 5, 0], "target": [0, 0, 0]}})", {"camera.up", "parallel"}},
        {R"({"camera": {"up": [0, 0, 0]}})", {"camera.up", "must be non-zero"}},
        {R"({"camera": null})", {"camera", "expected an object, got null"}},
        {R"({"lights": [{"type": "area", "position": [0, 1, 0]}]})",
         {"lights[0].type", "unknown light type 'area'; expected point, directional or spot"}},
        {R"({"lights": [{"type": "spot", "position": [0, 1, 0]}]})", {"lights[0].direction", "missing required field"}},
        {R"({"lights": [{"type": "spot", "direction": [0, -1, 0]}]})",
         {"lights[0].position", "missing required field"}},
        {spot + R"("innerConeAngle": 0.6, "outerConeAngle": 0.5}]})",
         {"lights[0].innerConeAngle", "must not exceed outerConeAngle"}},
        {spot + R"("innerConeAngle": 0.9}]})", {"lights[0].innerConeAngle", "must not exceed outerConeAngle"}},
        {spot + R"("outerConeAngle": 1.6}]})", {"lights[0].outerConeAngle", "must be in [0, 1.5708]"}},
        {spot + R"("innerConeAngle": -0.1}]})", {"lights[0].innerConeAngle", "must be in [0, 1.5708]"}},
        {spot + R"("outerConeAngle": "wide"}]})", {"lights[0].outerConeAngle", "expected a number, got string"}},
        {spot + R"("range": -1}]})", {"lights[0].range", "must be > 0"}},
        {spot + R"("range": 0}]})", {"lights[0].range", "must be > 0"}},
        {light + R"("range": -2}]})", {"lights[0].range", "must be > 0"}},
        {R"({"lights": [{"position": [0, 1, 0]}]})", {"lights[0].type", "missing required field"}},
        {R"({"lights": [{"type": "point"}]})", {"lights[0].position", "missing required field"}},
        {R"({"lights": [{"type": "directional"}]})", {"lights[0].direction", "missing required field"}},
        {R"({"lights": [{"type": "directional", "direction": [0, 0, 0]}]})", {"lights[0].direction", "non-zero"}},
        {light + R"("color": [-1, 1, 1]}]})", {"lights[0].color[0]", "must be >= 0"}},
        {dirLight + R"("color": "white"}]})", {"lights[0].color", "expected 3 numbers or one number, got string"}},
        {light + R"("attenuation": [0, 0, 0]}]})", {"lights[0].attenuation", "must not be all zero"}},
        {light + R"("attenuation": [1, -0.1, 0]}]})", {"lights[0].attenuation[1]", "must be >= 0"}},
        {light + R"("attenuation": 1}]})", {"lights[0].attenuation", "expected an array of 3 numbers"}},
        {tooMany, {"lights", "too many lights: 33; at most 32"}},
        {R"({"lights": {}})", {"lights", "expected an array, got object"}},
        {R"({"objects": [{"type": "sphere", "radius": 1}]})", {"objects[0].center", "missing required field"}},
        {R"({"objects": [{"type": "sphere", "center": [0, 0, 0]}]})", {"objects[0].radius", "missing required"}},
        {ball + R"("center": [0, 0, 0], "radius": 0}]})", {"objects[0].radius", "must be > 0"}},
        {ball + R"("center": [1e39, 0, 0], "radius": 1}]})", {"objects[0].center[0]", "must be finite"}},
        {R"({"objects": [{"type": "cube"}]})", {"objects[0].type", "unknown object type 'cube'"}},
        {R"({"objects": [3]})", {"objects[0]", "expected an object, got number"}},
        {plane + R"("normal": [0, 0, 0]}]})", {"objects[0].normal", "must be non-zero"}},
        {plane + R"("offset": 1, "point": [0, 1, 0]}]})", {"objects[0].point", "not both"}},
        {plane + R"("checker": {"size": 0}}]})", {"objects[0].checker.size", "must be > 0"}},
        {plane + R"("checker": {"md2": "grey"}}]})", {"objects[0].checker.md2", "expected 3 numbers or one number"}},
        {R"({"objects": [{"type": "mesh"}]})", {"objects[0].source", "missing required field"}},
        {R"({"objects": [{"type": "mesh", "source": ""}]})", {"objects[0].source", "must not be empty"}},
        {mesh + R"("transform": {}, "matrix": []}]})", {"objects[0].matrix", "not both"}},
        {mesh + R"("matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0]}]})",
         {"objects[0].matrix", "expected 16 numbers"}},
        {mesh + R"("matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1]}]})", {"objects[0].matrix", "affine"}},
        {mesh + R"("matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]}]})",
         {"objects[0].matrix", "invertible"}},
        {mesh + R"("transform": {"scale": 0}}]})", {"objects[0].transform.scale", "must be non-zero"}},
        {mesh + R"("transform": {"scale": [1, 0, 1]}}]})", {"objects[0].transform.scale[1]", "must be non-zero"}},
        {mesh + R"("transform": {"scale": 1e-38}}]})", {"objects[0].transform", "invertible"}},
        {mesh + R"("transform": {"rotate": [0, 90]}}]})", {"objects[0].transform.rotate", "expected 3 numbers, got 2"}},
        {mesh + R"("material": {"s": 1e5}}]})", {"objects[0].material.s", "must be in [0, 10000]"}},
        {R"({"materials": {"gold": {"s": -3}}})", {"materials.gold.s", "must be in [0, 10000]"}},
        {R"({"materials": {"my gold": {"ior": -3}}})", {"materials[\"my gold\"].ior", "must be > 0"}},
        {R"({"materials": []})", {"materials", "expected an object, got array"}},
        {R"({"maxDepth": 65})", {"maxDepth", "must be in [0, 64]"}},
        {R"({"display": {"exposure": 40}})", {"display.exposure", "must be in [-16, 16] stops, got 40"}},
        {R"({"display": {"exposure": -16.5}})", {"display.exposure", "must be in [-16, 16] stops, got -16.5"}},
        {R"({"display": {"exposure": true}})", {"display.exposure", "expected a number"}},
        {R"({"display": {"viewTransform": "aces"}})",
         {"display.viewTransform", "unknown view transform 'aces'; expected standard or filmic"}},
        {R"({"display": []})", {"display", "expected an object, got array"}},
        {R"({"maxDepth": -1})", {"maxDepth", "must be in [0, 64]"}},
        {R"({"maxDepth": 2.5})", {"maxDepth", "expected an integer"}},
        {R"({"ambient": [0.1, 0.1, -0.1]})", {"ambient[2]", "must be >= 0"}},
        {R"({"raster": {"shadowMapSize": 5}})",
         {"raster.shadowMapSize", "expected \"auto\" or an integer in 16..8192, got 5"}},
        {R"({"raster": {"shadowMapSize": 16384}})", {"raster.shadowMapSize", "integer in 16..8192, got 16384"}},
        {R"({"raster": {"shadowMapSize": 1024.5}})", {"raster.shadowMapSize", "got 1024.5"}},
        {R"({"raster": {"shadowMapSize": -1024}})", {"raster.shadowMapSize", "got -1024"}},
        {R"({"raster": {"shadowMapSize": "big"}})", {"raster.shadowMapSize", "got \"big\""}},
        {R"({"raster": {"shadowMapSize": true}})", {"raster.shadowMapSize", "got true"}},
        {R"({"raster": {"depthBias": -0.5}})", {"raster.depthBias", "must be in [0, 64], got -0.5"}},
        {R"({"raster": {"depthBias": "1"}})", {"raster.depthBias", "expected a number, got string"}},
        {R"({"raster": {"normalBias": 65}})", {"raster.normalBias", "must be in [0, 64], got 65"}},
        {R"({"raster": {"pcf": 1}})", {"raster.pcf", "expected true or false, got number"}},
        {R"({"raster": {"reflectionCubeSize": 4}})", {"raster.reflectionCubeSize", "must be in [8, 2048], got 4"}},
        {R"({"raster": {"reflectionCubeSize": 4096}})", {"raster.reflectionCubeSize", "must be in [8, 2048]"}},
        {R"({"raster": {"reflectionCubeSize": 100.5}})", {"raster.reflectionCubeSize", "expected an integer"}},
        {R"({"raster": [1024]})", {"raster", "expected an object, got array"}},
        {R"({"background": "black"})", {"background", "expected 3 numbers or one number, got string"}},
        {R"({"model": "gouraud"})",
         {"model", "unknown shading model 'gouraud'; expected phong, blinn-phong, pbr or disney"}},
        {R"({"model": 1})", {"model", "expected a string, got number"}},
        {R"({"terms": {"shadows": "yes"}})", {"terms.shadows", "expected true or false, got string"}},
        {R"({"title": 5})", {"title", "expected a string, got number"}},
        {R"({"shadelab": 2})", {"shadelab", "format version 2"}},
        {R"({"shadelab": 0})", {"shadelab", "must be in [1, "}},
        {"{\n  \"title\": \"x\",\n  \"notes\": y\n}", {"line 3, column 12", "syntax error while parsing value"}},
        {"{\"title\": \"h\xC3\xA9llo\", x}", {"line 1, column 20", "syntax error"}},
        {"", {"line 1, column 1", "unexpected end of input"}},
        {R"({"title": "x",})", {"line 1, column 15", "syntax error"}},
        {R"({"radius": 1e400})", {"", "number overflow"}},
    };
    for (const auto& [json, c] : cases) {
        SCOPED_TRACE(json);
        try {
            parse(json);
            ADD_FAILURE() << "no error; expected " << c.place << ": " << c.reason;
        } catch (const InputError& e) {
            std::string what = e.what();
            std::string prefix = std::string("a.json: ") + (c.place[0] ? std::string(c.place) + ": " : "");
            EXPECT_EQ(what.rfind(prefix, 0), 0u) << what;
            EXPECT_NE(what.find(c.reason), std::string::npos) << what;
            EXPECT_EQ(e.file(), "a.json");
        }
    }
}

TEST(SceneJson, ErrorMessageIsOneLineInTheDocumentedShape) {
    try {
        parse(R"({"lights": [{"type": "point", "position": [0, 1, 0]}, {"type": "point", "position": [0, 1, 0]},
                             {"type": "point", "position": [0, 1, 0], "color": [1, 1]}]})");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "a.json: lights[2].color: expected 3 numbers, got 2");
    }
    try {
        parse("{\"a\": 1,\n  x}");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "a.json: line 2, column 3: syntax error while parsing object key - invalid literal; "
                     "last read: '1,<U+000A>  x'; expected string literal");
    }
}

}  // namespace
}  // namespace shadelab
