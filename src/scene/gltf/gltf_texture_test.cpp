// glTF textures as scene data (design.md §9): base-colour images decoded from sRGB to linear with their mip
// chain and sampler, TEXCOORD_0 imported, BoxTextured in each of its forms, and hostile images (truncated,
// undecodable, a PNG claiming 65536 × 65536, missing, out of their buffer) each giving one warning line and
// the factor alone, without decoding anything large.
#include "gltf_test_util.h"

#include "image/png.h"
#include "scene/gltf/gltf_textures.h"
#include "util/error_line.h"

#include <stb_image_write.h>
#include <glm/vec4.hpp>

namespace shadelab::gltftest {
namespace {

// 4×4 RGBA with distinct sRGB values.
Image8 checker4() {
    Image8 img;
    img.width = img.height = 4;
    img.channels = 4;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            img.data.insert(img.data.end(), {uint8_t(60 * x), uint8_t(60 * y), uint8_t(200 - 10 * (x + 4 * y)), 255});
    return img;
}

std::string pngBytes(const Image8& img) {
    const std::vector<uint8_t> b = encodePng(img);
    return std::string(b.begin(), b.end());
}

// A unit quad with TEXCOORD_0 (u along +x, v = 0 at the top edge, y = 1) and material 0 textured by
// texture 0 from image 0, whose JSON is `image`. `extraBytes` is appended to the buffer (bufferView 4).
std::string texturedQuad(const std::string& image, const std::string& extraBytes = "",
                         const std::string& sampler = "{\"magFilter\":9728,\"minFilter\":9728}") {
    std::string bytes;
    appendBytes(bytes, std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    appendBytes(bytes, std::vector<glm::vec3>{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    appendBytes(bytes, std::vector<glm::vec2>{{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    appendBytes(bytes, std::vector<uint32_t>{0, 1, 2, 0, 2, 3});
    const size_t extraOffset = bytes.size();
    bytes += extraBytes;
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},"indices":3,"material":0}]}],
      "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"baseColorTexture":{"index":0}}}],
      "textures":[{"source":0,"sampler":0}],"samplers":[)" +
           sampler + R"(],"images":[)" + image + R"(],
      "buffers":[{"byteLength":)" +
           std::to_string(bytes.size()) + R"(,"uri":"data:application/octet-stream;base64,)" + base64(bytes) +
           R"("}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":48},
                     {"buffer":0,"byteOffset":96,"byteLength":32},{"buffer":0,"byteOffset":128,"byteLength":24},
                     {"buffer":0,"byteOffset":)" +
           std::to_string(extraOffset) + R"(,"byteLength":)" + std::to_string(extraBytes.size()) + R"(}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
                   {"bufferView":1,"componentType":5126,"count":4,"type":"VEC3"},
                   {"bufferView":2,"componentType":5126,"count":4,"type":"VEC2"},
                   {"bufferView":3,"componentType":5125,"count":6,"type":"SCALAR"}]})";
}

std::string dataUri(const std::string& bytes, const char* mime = "image/png") {
    return std::string("{\"uri\":\"data:") + mime + ";base64," + base64(bytes) + "\"}";
}

float srgbDecode(uint8_t c) {
    const double v = c / 255.0;
    return float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

TEST(GltfTextures, EmbeddedPngDecodesToLinearTexelsWithTexcoords) {
    const Image8 img = checker4();
    for (const std::string& image :
         {dataUri(pngBytes(img)), std::string(R"({"bufferView":4,"mimeType":"image/png"})")}) {
        const bool inBuffer = image.find("bufferView") != std::string::npos;
        const GltfImport g = importGltfBytes(texturedQuad(image, inBuffer ? pngBytes(img) : ""), false, "quad.gltf");
        ASSERT_EQ(g.parts.size(), 1u);
        const TextureBinding& b = g.parts[0].material.baseColorTexture;
        ASSERT_TRUE(b) << image;
        EXPECT_TRUE(b.texture->srgb);
        ASSERT_EQ(b.texture->width(), 4);
        ASSERT_EQ(b.texture->levels.size(), 3u);
        EXPECT_FALSE(b.sampler.magLinear);
        EXPECT_FALSE(b.sampler.mipmaps);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                // Level 0 keeps the file's codes; they decode to the exact value (texel_decode.h's tables).
                const glm::vec4 t = b.texture->texel(0, x, y);
                const uint8_t* p = img.pixel(x, y);
                EXPECT_EQ(b.texture->levels[0].texels[size_t(4 * (4 * y + x))], p[0]);
                EXPECT_NEAR(t.r, srgbDecode(p[0]), srgbDecode(p[0]) / 2048.0f);
                EXPECT_NEAR(t.g, srgbDecode(p[1]), srgbDecode(p[1]) / 2048.0f);
                EXPECT_NEAR(t.b, srgbDecode(p[2]), srgbDecode(p[2]) / 2048.0f);
                EXPECT_EQ(t.a, 1.0f);
                // Negative control: the undecoded value differs (sRGB decoding is not a no-op here).
                if (p[0] > 10 && p[0] < 250) {
                    EXPECT_GT(std::abs(t.r - p[0] / 255.0f), 0.01f);
                }
            }
        // Mip levels average in linear space: the last level is the mean of level 0, encoded to 8 bits.
        glm::vec4 mean(0.0f);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) mean += b.texture->texel(0, x, y) / 16.0f;
        const uint8_t* last = &b.texture->levels.back().texels[0];
        for (int k = 0; k < 4; ++k) EXPECT_EQ(last[k], encodeTexelChannel(mean[k], k < 3)) << k;
        // Negative control: averaging the codes themselves (sRGB space) gives another, darker mean.
        float codeMean = 0.0f;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) codeMean += img.pixel(x, y)[0] / 16.0f;
        EXPECT_GT(std::abs(float(last[0]) - codeMean), 2.0f);
        const MeshGeometry& geo = *g.parts[0].geometry;
        ASSERT_EQ(geo.texcoords0.size(), 4u);
        EXPECT_EQ(geo.texcoords0[3], glm::vec2(0.0f, 0.0f));
        EXPECT_FALSE(anyWarningContains(g, "images[0]"));
    }
}

TEST(GltfTextures, OddSizesKeepTheMeanThroughTheChain) {
    const std::vector<uint8_t> rgba = {0, 0, 0, 0, 255, 255, 255, 255, 30, 60, 90, 120};  // 3 × 1
    const auto tex = makeTexture("odd", rgba.data(), 3, 1, false);
    ASSERT_EQ(tex->levels.size(), 2u);
    EXPECT_EQ(tex->levels[1].width, 1);
    const glm::vec4 want = (glm::vec4(0) + glm::vec4(1) + glm::vec4(30, 60, 90, 120) / 255.0f) / 3.0f;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(tex->levels[1].texels[size_t(k)], encodeTexelChannel(want[k], false)) << k;
    EXPECT_EQ(tex->texelBytes(), textureBytesFor(3, 1));
}

TEST(GltfTextures, BoxTexturedInEachFormHasItsTexture) {
    REQUIRE_MODELS();
    std::shared_ptr<const Texture> first;
    for (const char* path : {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                             "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        const GltfImport g = importGltf(model(path));
        ASSERT_EQ(g.parts.size(), 1u) << path;
        const TextureBinding& b = g.parts[0].material.baseColorTexture;
        ASSERT_TRUE(b) << path;
        EXPECT_EQ(b.texture->width(), 211);
        EXPECT_EQ(b.texture->height(), 211);
        EXPECT_EQ(b.texture->levels.size(), 8u);  // 211, 105, 52, 26, 13, 6, 3, 1
        // The .gltf form's sampler is mirrored × clamp; the .glb and embedded forms' is repeat × repeat.
        const bool separate = std::string(path).find("-glTF/") != std::string::npos;
        EXPECT_EQ(b.sampler.wrapS, separate ? TextureWrap::MirroredRepeat : TextureWrap::Repeat) << path;
        EXPECT_EQ(b.sampler.wrapT, separate ? TextureWrap::ClampToEdge : TextureWrap::Repeat) << path;
        EXPECT_TRUE(b.sampler.magLinear);
        EXPECT_FALSE(b.sampler.minLinear);  // 9986 NEAREST_MIPMAP_LINEAR
        EXPECT_TRUE(b.sampler.mipmaps);
        EXPECT_EQ(g.parts[0].geometry->texcoords0.size(), g.parts[0].geometry->positions.size());
        if (!first) {
            first = b.texture;
            // The Cesium logo: mostly white-grey with a green-blue mark; its mean is light and not grey.
            const glm::vec4 mean = first->texel(first->levels.size() - 1, 0, 0);
            std::printf("BoxTextured mean texel (linear): %.4f %.4f %.4f %.4f\n", mean.r, mean.g, mean.b, mean.a);
        } else {
            ASSERT_EQ(b.texture->levels[0].texels.size(), first->levels[0].texels.size());
            EXPECT_TRUE(b.texture->levels[0].texels == first->levels[0].texels) << path << " decodes differently";
        }
    }
}

// Each hostile image: the import succeeds, one warning line names the image and the fallback (and no other
// line repeats it: tinygltf's own words about an external file are left out), and the material has no texture.
void expectFallback(const std::string& gltf, const std::string& reason) {
    const GltfImport g = importGltfBytes(gltf, false, "hostile.gltf");
    ASSERT_EQ(g.parts.size(), 1u);
    EXPECT_FALSE(g.parts[0].material.baseColorTexture) << reason;
    size_t lines = 0;
    for (const std::string& w : g.warnings)
        if (contains(w, "images[0]")) {
            ++lines;
            EXPECT_TRUE(contains(w, reason)) << w;
            EXPECT_TRUE(contains(w, "using the factor alone")) << w;
            EXPECT_EQ(w.find('\n'), std::string::npos);
        }
    EXPECT_EQ(lines, 1u) << reason;
    std::string all;
    for (const std::string& w : g.warnings) all += w + " | ";
    EXPECT_EQ(g.warnings.size(), 1u) << reason << ": " << all;
}

std::string bombPng() {
    // Signature and an IHDR claiming 65536 × 65536 RGBA, then nothing: decoding it would need 16 GiB.
    std::string b = "\x89PNG\r\n\x1a\n";
    b += std::string("\0\0\0\x0dIHDR", 8);
    b += std::string("\0\x01\0\0\0\x01\0\0\x08\x06\0\0\0", 13);
    b += std::string("\0\0\0\0", 4);  // CRC, unchecked by the header read
    return b;
}

TEST(GltfTextures, HostileImagesFallBackToTheFactor) {
    const std::string png = pngBytes(checker4());
    expectFallback(texturedQuad(dataUri(png.substr(0, png.size() / 2))), "cannot decode");
    expectFallback(texturedQuad(dataUri("this is not an image")), "not a PNG or JPEG");
    expectFallback(texturedQuad(dataUri(bombPng())), "65536x65536, over the limit of 8192");
    expectFallback(texturedQuad(R"({"uri":"missing.png"})"), "cannot read \"missing.png\"");
    expectFallback(texturedQuad(R"({"bufferView":4})"), "image has no bytes");
    // A buffer view that does not exist is a malformed file (tinygltf refuses it): one line, exit 1.
    try {
        importGltfBytes(texturedQuad(R"({"bufferView":9})"), false, "hostile.gltf");
        FAIL() << "accepted an image in bufferView 9 of 5";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "hostile.gltf")) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
    // A JPEG header with nothing after it.
    expectFallback(texturedQuad(dataUri(std::string("\xFF\xD8\xFF\xE0", 4), "image/jpeg")), "image");
}

TEST(GltfTextures, TheBombIsRefusedBeforeDecodingEvenWithoutTheSideLimit) {
    try {
        gltf::decodeTexture(bombPng(), "bomb", true, uint64_t(1) << 20, uint64_t(1) << 30, uint64_t(1) << 40);
        FAIL() << "decoded a 65536 x 65536 PNG";
    } catch (const std::runtime_error& e) {
        EXPECT_TRUE(contains(e.what(), "over the")) << e.what();
        EXPECT_TRUE(contains(e.what(), "texture budget")) << e.what();
    }
}

TEST(GltfTextures, TextureTransformIsRead) {
    std::string gltf = texturedQuad(dataUri(pngBytes(checker4())));
    const std::string info = "\"baseColorTexture\":{\"index\":0}";
    gltf.replace(gltf.find(info), info.size(),
                 "\"baseColorTexture\":{\"index\":0,\"extensions\":{\"KHR_texture_transform\":"
                 "{\"offset\":[0.25,-1],\"rotation\":0.5,\"scale\":[2,3]}}}");
    const GltfImport g = importGltfBytes(gltf, false, "t.gltf");
    const TextureBinding& b = g.parts[0].material.baseColorTexture;
    ASSERT_TRUE(b);
    EXPECT_EQ(b.offset, glm::vec2(0.25f, -1.0f));
    EXPECT_EQ(b.rotation, 0.5f);
    EXPECT_EQ(b.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_FALSE(anyWarningContains(g, "KHR_texture_transform"));
    // The spec's matrix: rotation [[cos, sin], [-sin, cos]] times scale.
    const glm::vec4 m = b.uvMatrix();
    EXPECT_NEAR(m.x, 2.0f * std::cos(0.5f), 1e-6f);
    EXPECT_NEAR(m.y, 3.0f * std::sin(0.5f), 1e-6f);
    EXPECT_NEAR(m.z, -2.0f * std::sin(0.5f), 1e-6f);
    EXPECT_NEAR(m.w, 3.0f * std::cos(0.5f), 1e-6f);
}

TEST(GltfTextures, TextureCountLimit) {
    GltfLimits limits;
    limits.maxTextures = 0;
    const GltfImport g = importGltfBytes(texturedQuad(dataUri(pngBytes(checker4()))), false, "q.gltf", limits);
    EXPECT_FALSE(g.parts[0].material.baseColorTexture);
    EXPECT_TRUE(anyWarningContains(g, "over the limit of 0 textures per model"));
}

// A real 8 × 8 grey JPEG (stb_image_write) whose frame header then claims `w` × `h`: a file of a few hundred
// bytes that stb_image decodes to whatever size it claims, filling what the data lacks.
std::string forgedJpeg(uint16_t w, uint16_t h) {
    std::string jpeg;
    const std::vector<uint8_t> grey(64, 128);
    stbi_write_jpg_to_func(
        [](void* out, void* data, int size) {
            static_cast<std::string*>(out)->append(static_cast<const char*>(data), size_t(size));
        },
        &jpeg, 8, 8, 1, grey.data(), 90);
    const size_t sof = jpeg.find("\xFF\xC0");  // baseline frame header: FF C0, length, precision, height, width
    EXPECT_NE(sof, std::string::npos);
    jpeg[sof + 5] = char(h >> 8), jpeg[sof + 6] = char(h & 0xFF);
    jpeg[sof + 7] = char(w >> 8), jpeg[sof + 8] = char(w & 0xFF);
    return jpeg;
}

TEST(GltfTextures, AForgedJpegIsRefusedByItsHeadersPixelCount) {
    const std::string bomb = forgedJpeg(8000, 8000);
    ASSERT_LT(bomb.size(), 2000u);
    // 8000² is within the side limit (8192) and the texture budget; the pixel limit refuses it unread.
    expectFallback(texturedQuad(dataUri(bomb, "image/jpeg")),
                   "8000x8000 = 64000000 pixels, over the limit of 16777216 pixels");
    // Negative control: the same forgery at a size the limits allow decodes, from its few hundred bytes, to
    // all the pixels it claims: only the header's size stands between the file and 8000² (a gigabyte).
    const auto small = gltf::decodeTexture(forgedJpeg(300, 200), "forged", false, 8192, uint64_t(1) << 30);
    EXPECT_EQ(small->width(), 300);
    EXPECT_EQ(small->height(), 200);
}

TEST(GltfTextures, ThePixelLimitCountsEveryImage) {
    const std::string png = pngBytes(checker4());  // 16 pixels
    GltfLimits limits;
    limits.maxTexturePixels = 15;
    for (const std::string& gltf : {texturedQuad(dataUri(png)), texturedQuad(R"({"bufferView":4})", png)}) {
        const GltfImport refused = importGltfBytes(gltf, false, "p.gltf", limits);
        EXPECT_FALSE(refused.parts[0].material.baseColorTexture);
        EXPECT_TRUE(anyWarningContains(refused, "4x4 = 16 pixels, over the limit of 15 pixels"));
        // Negative control: at 16 pixels the same image decodes.
        limits.maxTexturePixels = 16;
        EXPECT_TRUE(importGltfBytes(gltf, false, "p.gltf", limits).parts[0].material.baseColorTexture);
        limits.maxTexturePixels = 15;
    }
}

TEST(GltfTextures, ADataUriImageCountsAgainstTheImageByteLimit) {
    const std::string png = pngBytes(checker4());
    GltfLimits limits;
    limits.maxImageBytes = png.size() - 1;
    const std::string over = "image of " + std::to_string(png.size()) + " bytes exceeds the limit of " +
                             std::to_string(png.size() - 1) + " bytes";
    // Before, a data: URI skipped the limit an external file meets; now it is the same warning.
    const GltfImport refused = importGltfBytes(texturedQuad(dataUri(png)), false, "d.gltf", limits);
    EXPECT_FALSE(refused.parts[0].material.baseColorTexture);
    EXPECT_TRUE(anyWarningContains(refused, over));
    // A buffer view declares its size in the JSON, where the limit refuses the file (docs/gltf-import.md).
    EXPECT_THROW(importGltfBytes(texturedQuad(R"({"bufferView":4})", png), false, "d.gltf", limits), InputError);
    // Negative control: a limit of exactly its size lets the data: URI image through.
    limits.maxImageBytes = png.size();
    EXPECT_TRUE(
        importGltfBytes(texturedQuad(dataUri(png)), false, "d.gltf", limits).parts[0].material.baseColorTexture);
}

// `json` as a GLB: its JSON chunk, then a 4-byte BIN chunk that must come through the repair unchanged.
std::string glbOf(std::string json) {
    json.append((4 - json.size() % 4) % 4, ' ');
    auto u32 = [](std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    std::string glb;
    u32(glb, 0x46546C67u);  // glTF
    u32(glb, 2);
    u32(glb, uint32_t(12 + 8 + json.size() + 8 + 4));
    u32(glb, uint32_t(json.size()));
    u32(glb, 0x4E4F534Au);  // JSON
    glb += json;
    u32(glb, 4);
    u32(glb, 0x004E4942u);  // BIN
    return glb + std::string(4, '\0');
}

TEST(GltfTextures, BadBase64InADataUriIsAWarning) {
    // tinygltf refuses the whole file when an image's data: URI yields no byte; shadelab warns about the image.
    expectFallback(texturedQuad(R"({"uri":"data:image/png;base64,!!!!"})"), "its data: URI is not base64");
    expectFallback(texturedQuad(R"({"uri":"data:image/png;base64,"})"), "its data: URI holds no data");
    // The NUL of a JSON "\u0000" stays in the reason as \x00 (the warning is a std::string, then a C string).
    expectFallback(texturedQuad(R"({"uri":"data:image/png;base64,\u0000AAAA"})"), "begins \"\\x00AAAA\"");
    const GltfImport glb = importGltfBytes(glbOf(texturedQuad(R"({"uri":"data:image/jpeg;base64,*"})")), true, "b.glb");
    ASSERT_EQ(glb.parts.size(), 1u);
    EXPECT_FALSE(glb.parts[0].material.baseColorTexture);
    EXPECT_TRUE(anyWarningContains(glb,
                                   "images[0] (used by materials[0].pbrMetallicRoughness.baseColorTexture): "
                                   "its data: URI is not base64"));
    // The other images are the file's own: the texture that uses image 1 decodes beside the broken image 0.
    std::string two = texturedQuad(R"({"uri":"data:image/png;base64,!!"},)" + dataUri(pngBytes(checker4())));
    two.replace(two.find("\"source\":0"), 10, "\"source\":1");
    const GltfImport g = importGltfBytes(two, false, "two.gltf");
    EXPECT_TRUE(g.parts[0].material.baseColorTexture);
    EXPECT_TRUE(g.warnings.empty());
    // Negative control: a buffer's bad base64 is still an error (a buffer is required, not a texture).
    std::string badBuffer = texturedQuad(dataUri(pngBytes(checker4())));
    badBuffer.replace(badBuffer.find("octet-stream;base64,") + 20, 0, "!");
    EXPECT_THROW(importGltfBytes(badBuffer, false, "buffer.gltf"), InputError);
}

TEST(GltfTextures, ANegativeTextureIndexIsOutOfRange) {
    const std::string png = dataUri(pngBytes(checker4()));
    for (const std::string index : {"-1", "-7"}) {
        std::string gltf = texturedQuad(png);
        gltf.replace(gltf.find("\"baseColorTexture\":{\"index\":0}"), 30,
                     "\"baseColorTexture\":{\"index\":" + index + "}");
        const GltfImport g = importGltfBytes(gltf, false, "n.gltf");
        EXPECT_FALSE(g.parts[0].material.baseColorTexture);
        EXPECT_TRUE(anyWarningContains(g, "materials[0].pbrMetallicRoughness.baseColorTexture: texture " + index +
                                              " out of range (1 textures); using the factor alone"))
            << index;
    }
    // A material's own texture infos (normal, occlusion, emissive) are held to the same rule.
    std::string normal = texturedQuad(png);
    normal.replace(normal.find("\"pbrMetallicRoughness\""), 0, "\"normalTexture\":{\"index\":-1},");
    EXPECT_TRUE(anyWarningContains(importGltfBytes(normal, false, "n.gltf"),
                                   "materials[0].normalTexture: texture -1 out of range"));
    // Negative control: a material without a texture info warns about none.
    std::string none = texturedQuad(png);
    none.replace(none.find(",\"baseColorTexture\":{\"index\":0}"), 31, "");
    const GltfImport g = importGltfBytes(none, false, "n.gltf");
    EXPECT_FALSE(g.parts[0].material.baseColorTexture);
    EXPECT_FALSE(anyWarningContains(g, "out of range")) << (g.warnings.empty() ? "" : g.warnings[0]);
}

TEST(GltfTextures, NewlinesInAnImageUriStayInOneWarning) {
    // tinygltf's "File not found : data:x\ny\nz" once became three warnings: "y" and "z" on lines of their own.
    for (const char* uri : {"data:x\\ny\\nz", "data:x%0Ay%0Az"}) {
        const GltfImport g = importGltfBytes(texturedQuad(std::string(R"({"uri":")") + uri + "\"}"), false, "nl.gltf");
        std::string all;
        for (const std::string& w : g.warnings) all += w + " | ";
        ASSERT_EQ(g.warnings.size(), 1u) << all;  // the split made 3
        EXPECT_TRUE(contains(g.warnings[0], "images[0]")) << all;
        // The newlines are the URI's own and reach the terminal escaped, on the warning's one line.
        EXPECT_EQ(errorLine(g.warnings[0]).find('\n'), std::string::npos);
    }
}

}  // namespace
}  // namespace shadelab::gltftest
