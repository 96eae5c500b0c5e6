// JsonNode: a read-only view of one value in a parsed JSON document that knows its JSON path
// ("objects[2].material.s"), with typed, range-checked getters that throw InputError naming that path.
// Shared by the scene loader and the viewer's --script reader; not a general JSON library.
#pragma once

#include "util/name_table.h"

#include <glm/vec3.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

using WarnFn = void (*)(const std::string& line);

// Parses JSON text (comments allowed). A syntax error throws InputError(file, "line L, column C", reason).
nlohmann::json parseJsonText(const std::string& text, const std::string& file);

// "null", "boolean", "number", "string", "array" or "object".
const char* jsonTypeName(const nlohmann::json& j);

class JsonNode {
public:
    JsonNode(const nlohmann::json& j, std::string path, const std::string& file, WarnFn warn)
        : j_(&j), path_(std::move(path)), file_(&file), warn_(warn) {}

    const nlohmann::json& json() const { return *j_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& reason) const;
    // Fails at the path of `key` inside this object, whether or not the key is present.
    [[noreturn]] void failAt(const std::string& key, const std::string& reason) const;
    void warn(const std::string& reason) const;

    // Objects. `child` throws "missing required field" at the child's path when the key is absent.
    const JsonNode& requireObject() const;
    bool has(const std::string& key) const;
    JsonNode child(const std::string& key) const;
    std::optional<JsonNode> find(const std::string& key) const;
    // Warns about every key not in `known`, suggesting a close known key when there is one.
    void warnUnknownKeys(std::initializer_list<const char*> known) const;
    void warnUnknownKeys(const std::vector<const char*>& known) const;

    // Arrays.
    size_t arraySize() const;
    JsonNode operator[](size_t i) const;

    // Scalars.
    bool boolean() const;
    std::string string() const;
    double number() const;      // any JSON number
    float finite() const;       // a number that is finite as a float
    float nonNegative() const;  // finite, >= 0
    float positive() const;     // finite, > 0
    float inRange(float lo, float hi, bool openLo, bool openHi) const;
    // `f` (this node's value) when |f| <= bound, else fails "must be at most <bound> in magnitude (<why>)".
    float within(float f, float bound, const char* why) const;
    int integerIn(int lo, int hi) const;
    // A string naming an entry of an enum's name table (util/name_table.h). Anything else fails with
    // "unknown <what> '<word>'; expected <the table's names>".
    template <typename E, size_t N>
    E oneOf(const EnumName<E> (&table)[N], const char* what) const {
        const std::string word = string();
        if (auto v = lookupName(table, word)) return *v;
        fail("unknown " + std::string(what) + " '" + word + "'; expected " + nameChoices(table));
    }

    // Vectors: exactly three finite numbers.
    glm::vec3 vec3() const;
    glm::vec3 vec3Within(float bound) const;  // each number's magnitude at most `bound`
    glm::vec3 nonZeroVec3() const;            // not (0, 0, 0)
    glm::vec3 unitVec3() const;               // non-zero, normalised (kept as written when already unit)
    // An RGB colour or coefficient: three numbers >= 0, or one number meaning grey.
    glm::vec3 rgb() const;
    glm::vec3 rgbUpTo(float max) const;  // the same, each at most `max`
    glm::vec3 unitRgb() const;           // the same, each in [0, 1] (a reflectance such as a base colour)

private:
    std::string childPath(const std::string& key) const;

    const nlohmann::json* j_;
    std::string path_;
    const std::string* file_;
    WarnFn warn_;
};

}  // namespace shadelab
