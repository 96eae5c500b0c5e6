// JsonNode: typed, path-tracking getters over nlohmann::json for the scene loader (json_reader.h).
// Every failure is an InputError "<file>: <json path>: <reason>".
#include "scene/json_reader.h"

#include "util/finite.h"

#include "util/input_error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace shadelab {

namespace {

// nlohmann's what() is "[json.exception.parse_error.101] parse error at line 1, column 4: <reason>";
// keep only <reason>, since the place is reported separately.
std::string nlohmannReason(const std::string& what) {
    std::string s = what;
    if (size_t p = s.find("] "); s.rfind("[json.exception.", 0) == 0 && p != std::string::npos) s.erase(0, p + 2);
    if (s.rfind("parse error", 0) == 0) {
        if (size_t p = s.find(": "); p != std::string::npos) s.erase(0, p + 2);
    }
    return s;
}

// 1-based line and column (in UTF-8 code points) of the 0-based byte offset `pos`.
std::string lineColumn(const std::string& text, size_t pos) {
    pos = std::min(pos, text.size());
    size_t line = 1, column = 1;
    for (size_t i = 0; i < pos; ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Levenshtein distance, for "did you mean" hints.
size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

bool isIdentifier(const std::string& key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    return std::all_of(key.begin(), key.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; });
}

std::string formatBound(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
    return buf;
}

}  // namespace

nlohmann::json parseJsonText(const std::string& text, const std::string& file) {
    try {
        return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte is the 1-based offset of the last byte read, i.e. where parsing stopped.
        throw InputError(file, lineColumn(text, e.byte == 0 ? 0 : e.byte - 1), nlohmannReason(e.what()));
    } catch (const nlohmann::json::exception& e) {  // e.g. out_of_range.406: number overflow
        throw InputError(file, nlohmannReason(e.what()));
    }
}

const char* jsonTypeName(const nlohmann::json& j) {
    if (j.is_null()) return "null";
    if (j.is_boolean()) return "boolean";
    if (j.is_number()) return "number";
    if (j.is_string()) return "string";
    if (j.is_array()) return "array";
    if (j.is_object()) return "object";
    return "value";
}

void JsonNode::fail(const std::string& reason) const { throw InputError(*file_, path_, reason); }

void JsonNode::failAt(const std::string& key, const std::string& reason) const {
    throw InputError(*file_, childPath(key), reason);
}

void JsonNode::warn(const std::string& reason) const {
    if (!warn_) return;
    std::string line = file_->empty() ? std::string() : *file_ + ": ";
    if (!path_.empty()) line += path_ + ": ";
    warn_(line + reason);
}

const JsonNode& JsonNode::requireObject() const {
    if (!j_->is_object()) fail(std::string("expected an object, got ") + jsonTypeName(*j_));
    return *this;
}

std::string JsonNode::childPath(const std::string& key) const {
    if (!isIdentifier(key)) return path_ + "[" + nlohmann::json(key).dump() + "]";
    return path_.empty() ? key : path_ + "." + key;
}

bool JsonNode::has(const std::string& key) const { return j_->is_object() && j_->contains(key); }

JsonNode JsonNode::child(const std::string& key) const {
    requireObject();
    std::string p = childPath(key);
    auto it = j_->find(key);
    if (it == j_->end()) JsonNode(*j_, p, *file_, warn_).fail("missing required field");
    return JsonNode(*it, p, *file_, warn_);
}

std::optional<JsonNode> JsonNode::find(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return child(key);
}

void JsonNode::warnUnknownKeys(std::initializer_list<const char*> known) const {
    warnUnknownKeys(std::vector<const char*>(known));
}

void JsonNode::warnUnknownKeys(const std::vector<const char*>& known) const {
    requireObject();
    for (auto it = j_->begin(); it != j_->end(); ++it) {
        const std::string& key = it.key();
        if (std::any_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) continue;
        std::string hint;
        size_t best = std::max<size_t>(1, key.size() / 3) + 1;
        for (const char* k : known) {
            size_t d = lower(key) == lower(k) ? 0 : editDistance(key, k);
            if (d < best) {
                best = d;
                hint = k;
            }
        }
        warn("unknown field '" + key + "' (ignored)" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
}

size_t JsonNode::arraySize() const {
    if (!j_->is_array()) fail(std::string("expected an array, got ") + jsonTypeName(*j_));
    return j_->size();
}

JsonNode JsonNode::operator[](size_t i) const {
    return JsonNode((*j_)[i], path_ + "[" + std::to_string(i) + "]", *file_, warn_);
}

bool JsonNode::boolean() const {
    if (!j_->is_boolean()) fail(std::string("expected true or false, got ") + jsonTypeName(*j_));
    return j_->get<bool>();
}

std::string JsonNode::string() const {
    if (!j_->is_string()) fail(std::string("expected a string, got ") + jsonTypeName(*j_));
    return j_->get<std::string>();
}

double JsonNode::number() const {
    if (!j_->is_number()) fail(std::string("expected a number, got ") + jsonTypeName(*j_));
    return j_->get<double>();
}

float JsonNode::finite() const {
    const std::optional<float> f = finiteFloat(number());
    if (!f) fail("must be finite (a float is at most 3.4e38), got " + j_->dump());
    return *f;
}

float JsonNode::nonNegative() const {
    float f = finite();
    if (!(f >= 0.0f)) fail("must be >= 0, got " + j_->dump());
    return f;
}

float JsonNode::positive() const {
    float f = finite();
    if (!(f > 0.0f)) fail("must be > 0, got " + j_->dump());
    return f;
}

float JsonNode::inRange(float lo, float hi, bool openLo, bool openHi) const {
    float f = finite();
    bool ok = (openLo ? f > lo : f >= lo) && (openHi ? f < hi : f <= hi);
    if (!ok)
        fail(std::string("must be in ") + (openLo ? "(" : "[") + formatBound(lo) + ", " + formatBound(hi) +
             (openHi ? ")" : "]") + ", got " + j_->dump());
    return f;
}

int JsonNode::integerIn(int lo, int hi) const {
    double d = number();
    if (d != std::floor(d)) fail("expected an integer, got " + j_->dump());
    if (d < lo || d > hi)
        fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + j_->dump());
    return static_cast<int>(d);
}

glm::vec3 JsonNode::vec3() const {
    if (!j_->is_array()) fail(std::string("expected an array of 3 numbers, got ") + jsonTypeName(*j_));
    if (j_->size() != 3) fail("expected 3 numbers, got " + std::to_string(j_->size()));
    return {(*this)[0].finite(), (*this)[1].finite(), (*this)[2].finite()};
}

glm::vec3 JsonNode::vec3Within(float bound) const {
    const glm::vec3 v = vec3();
    for (size_t i = 0; i < 3; ++i) (*this)[i].within(v[int(i)], bound, "the largest coordinate");
    return v;
}

float JsonNode::within(float f, float bound, const char* why) const {
    if (!(std::fabs(f) <= bound))
        fail("must be at most " + formatBound(bound) + " in magnitude (" + why + "), got " + j_->dump());
    return f;
}

glm::vec3 JsonNode::nonZeroVec3() const {
    glm::vec3 v = vec3();
    if (v == glm::vec3(0.0f)) fail("must be non-zero");
    return v;
}

glm::vec3 JsonNode::unitVec3() const {
    glm::vec3 v = nonZeroVec3();
    double x = v.x, y = v.y, z = v.z;
    double len2 = x * x + y * y + z * z;
    // Already unit to float precision: keep it bit for bit, so that save → load is exact.
    if (std::abs(len2 - 1.0) <= 1e-6) return v;
    double inv = 1.0 / std::sqrt(len2);
    glm::vec3 n(static_cast<float>(x * inv), static_cast<float>(y * inv), static_cast<float>(z * inv));
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || n == glm::vec3(0.0f))
        fail("cannot be normalised");
    return n;
}

glm::vec3 JsonNode::rgb() const {
    if (j_->is_number()) return glm::vec3(nonNegative());
    if (!j_->is_array()) fail(std::string("expected 3 numbers or one number, got ") + jsonTypeName(*j_));
    if (j_->size() != 3) fail("expected 3 numbers, got " + std::to_string(j_->size()));
    return {(*this)[0].nonNegative(), (*this)[1].nonNegative(), (*this)[2].nonNegative()};
}

glm::vec3 JsonNode::rgbUpTo(float max) const {
    const glm::vec3 c = rgb();
    if (j_->is_number()) return glm::vec3(within(c.x, max, "the largest radiance"));
    for (size_t i = 0; i < 3; ++i) (*this)[i].within(c[int(i)], max, "the largest radiance");
    return c;
}

glm::vec3 JsonNode::unitRgb() const {
    if (j_->is_number()) return glm::vec3(inRange(0.0f, 1.0f, false, false));
    if (!j_->is_array()) fail(std::string("expected 3 numbers or one number, got ") + jsonTypeName(*j_));
    if (j_->size() != 3) fail("expected 3 numbers, got " + std::to_string(j_->size()));
    return {(*this)[0].inRange(0.0f, 1.0f, false, false), (*this)[1].inRange(0.0f, 1.0f, false, false),
            (*this)[2].inRange(0.0f, 1.0f, false, false)};
}

}  // namespace shadelab
