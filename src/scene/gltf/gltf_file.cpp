// Reading a .gltf/.glb into a tinygltf::Model: file checks, the declared-size limits (gltf_limits.h),
// buffer and image files kept inside the model's folder unless allowed, images kept encoded. Walking the model is
// gltf_import.cpp.
#include "scene/gltf/gltf_file.h"

#include "scene/gltf/gltf_image_uris.h"
#include "util/error_line.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <new>
#include <stdexcept>

namespace shadelab::gltf {
namespace {

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(" \t\r\n");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

void appendLines(const std::string& text, std::vector<std::string>& out) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = trim(text.substr(start, end - start));
        if (!line.empty()) out.push_back(std::move(line));
        start = end + 1;
    }
}

// Images are not decoded here: a URI image's encoded bytes (a data URI's, or the external file's, already
// bounded by readInsideFolder) are kept in `image`, and a buffer view's are left in the buffer, since
// tinygltf does not check that view against its buffer. gltf_textures.cpp decodes what materials use.
bool keepEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                 int size, void*) {
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// The model's folder, for the file callbacks that resolve external buffers and images, keep them inside it
// and bound what is read of them.
struct FolderGuard {
    std::string baseDir;         // as given to tinygltf
    std::filesystem::path root;  // weakly canonical
    bool allowOutside = false;
    uint64_t maxSideFileBytes = 0;  // the largest declared buffer, or one image's limit if larger

    // tinygltf joins the folder and an absolute URI into "<baseDir>//abs"; undo that join.
    std::string resolve(const std::string& joined) const {
        const std::string prefix = baseDir + "/";
        if (joined.size() > prefix.size() && joined.compare(0, prefix.size(), prefix) == 0 &&
            joined[prefix.size()] == '/')
            return joined.substr(prefix.size());
        return joined;
    }
    bool contains(const std::string& file) const {
        std::error_code ec;
        const std::filesystem::path p = std::filesystem::weakly_canonical(file, ec);
        if (ec) return false;
        const std::filesystem::path rel = p.lexically_relative(root);
        return !rel.empty() && *rel.begin() != "..";
    }
};

// Whether an external file exists, by stat alone: nothing is opened here (a FIFO would block), and a path
// outside the folder is not even looked at, so that readInsideFolder refuses it by name.
bool existsResolved(const std::string& joined, void* user) {
    const FolderGuard& guard = *static_cast<const FolderGuard*>(user);
    const std::string file = guard.resolve(joined);
    if (file.find('\0') != std::string::npos || (!guard.allowOutside && !guard.contains(file))) return true;
    std::error_code ec;
    return std::filesystem::exists(file, ec);
}

// The path policy first, then util/read_file.h's checks (regular file, size bound) before any byte is read.
bool readInsideFolder(std::vector<unsigned char>* out, std::string* err, const std::string& joined, void* user) {
    const FolderGuard& guard = *static_cast<const FolderGuard*>(user);
    const std::string file = guard.resolve(joined);
    try {
        if (file.find('\0') != std::string::npos)
            throw InputError(errorLine(file), "file name contains a NUL character");
        if (!guard.allowOutside && !guard.contains(file))
            throw InputError(file, "outside the model's folder (pass --allow-external-paths to allow)");
        const std::string bytes = readFile(file, guard.maxSideFileBytes);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        if (err) *err += std::string("external file ") + e.what() + "\n";
        return false;
    }
}

// How each of tinygltf's warnings begins. tinygltf warns only about external images (buffers are required:
// their problems fail the load), and ends each warning with a newline; the image's URI and name inside one
// may hold newlines of their own ("%0A" in a URI, "\n" in a JSON string), so a line that begins no warning
// continues the one before.
constexpr const char* kTinygltfWarnings[] = {"File not found : ",
                                             "File read error : ",
                                             "File is empty : ",
                                             "File size mismatch : ",
                                             "Failed to load external 'uri' for image[",
                                             "Image data is empty for image["};

// tinygltf's warnings, one entry each, whatever newlines the user strings inside them hold (errorLine
// escapes those when the warning is printed).
std::vector<std::string> tinygltfWarnings(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        bool begins = out.empty();
        for (const char* prefix : kTinygltfWarnings) begins = begins || line.rfind(prefix, 0) == 0;
        if (begins)
            out.push_back(line);
        else
            out.back() += "\n" + line;
        start = end + 1;
    }
    for (std::string& w : out) w = trim(w);
    return out;
}

// tinygltf's own warnings about an external image it could not read ("File not found : ...", "File read
// error : ...", "Failed to load external 'uri' for image[...]"). gltf_textures.cpp reports each image a
// material uses in one clear line of its own, so these would only repeat it less clearly.
bool isExternalImageNoise(const std::string& warning) {
    for (const char* prefix : {"File not found : ", "File read error : ", "Failed to load external 'uri' for image["})
        if (warning.rfind(prefix, 0) == 0) return true;
    return false;
}

// Parses glTF text (`binary` false) or GLB bytes. External buffers resolve through `guard` (which refuses
// those outside the model's folder unless allowed); without a guard every external file is refused (the
// fuzzer's setting). `name` is the file named in errors.
LoadedModel parseGuarded(const std::string& bytes, bool binary, const std::string& name, const std::string& baseDir,
                         std::vector<std::string>& warnings, const FolderGuard* guard) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keepEncoded, nullptr);
    if (guard) {
        tinygltf::FsCallbacks guarded{&existsResolved, &tinygltf::ExpandFilePath, &readInsideFolder,
                                      &tinygltf::WriteWholeFile, const_cast<FolderGuard*>(guard)};
        loader.SetFsCallbacks(guarded);
    } else if (baseDir.empty()) {
        tinygltf::FsCallbacks noFiles{};
        noFiles.FileExists = [](const std::string&, void*) { return false; };
        noFiles.ExpandFilePath = [](const std::string& p, void*) { return p; };
        noFiles.ReadWholeFile = [](std::vector<unsigned char>*, std::string* err, const std::string& p, void*) {
            if (err) *err += "external file refused: " + p + "\n";
            return false;
        };
        noFiles.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
            return false;
        };
        loader.SetFsCallbacks(noFiles);
    }
    LoadedModel loaded;
    tinygltf::Model& model = loaded.model;
    std::string err, warn;
    // tinygltf can throw from inside (a GLB whose buffer has byteLength 0 indexes an empty vector): name the
    // file and say what went wrong in words, not in the standard library's.
    const auto load = [&](const std::string& input) {
        model = tinygltf::Model();
        err.clear();
        warn.clear();
        const auto* data = reinterpret_cast<const unsigned char*>(input.data());
        try {
            return binary
                       ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, unsigned(input.size()), baseDir)
                       : loader.LoadASCIIFromString(&model, &err, &warn, input.data(), unsigned(input.size()), baseDir);
        } catch (const std::bad_alloc&) {
            throw InputError(name, "out of memory while parsing the glTF");
        } catch (const std::out_of_range&) {
            throw InputError(name, "malformed glTF: the parser indexed past the end of an array (an empty buffer?)");
        } catch (const std::exception& e) {
            throw InputError(name, std::string("malformed glTF: the parser stopped (") + e.what() + ")");
        }
    };
    bool ok = load(bytes);
    // An image whose data: URI holds no base64 fails tinygltf's whole load, but a bad image is a warning
    // (gltf_textures.h): parse again with a placeholder for each such image, which the texture loader reports.
    if (!ok && isUndecodableImageUriError(err)) {
        ImageUriRepair repair = replaceUndecodableImageUris(bytes, binary);
        if (!repair.problems.empty()) {
            ok = load(repair.bytes);
            loaded.imageProblems = std::move(repair.problems);
        }
    }
    if (!ok) {
        std::vector<std::string> lines;
        appendLines(err, lines);
        std::string reason = lines.empty() ? std::string("tinygltf failed without a message") : lines.front();
        // tinygltf wraps readInsideFolder's reason in "File read error : <path> : "; the reason names the file.
        const size_t ours = reason.find("external file ");
        if (ours != std::string::npos) reason = reason.substr(ours);
        throw InputError(name, reason);
    }
    for (std::string& w : tinygltfWarnings(warn))
        if (!w.empty() && !isExternalImageNoise(w)) warnings.push_back(std::move(w));
    appendLines(err, warnings);  // tinygltf reports some recoverable schema problems in err and still succeeds
    return loaded;
}

}  // namespace

LoadedModel parseModel(const std::string& bytes, bool binary, const std::string& name, const std::string& baseDir,
                       std::vector<std::string>& warnings) {
    return parseGuarded(bytes, binary, name, baseDir, warnings, nullptr);
}

LoadedModel loadModel(const std::string& path, const GltfImportOptions& options, std::vector<std::string>& warnings) {
    if (path.find('\0') != std::string::npos) throw InputError(errorLine(path), "file name contains a NUL character");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(path, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "is a directory, not a glTF file");
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".glb" && ext != ".gltf") throw InputError(path, "expected a .gltf or .glb file");
    std::string baseDir = std::filesystem::path(path).parent_path().string();
    if (baseDir.empty()) baseDir = ".";
    FolderGuard guard;
    guard.baseDir = baseDir;
    guard.root = std::filesystem::weakly_canonical(baseDir, ec);
    guard.allowOutside = options.allowExternalPaths;
    if (ec) throw InputError(path, "cannot resolve the model's folder: " + ec.message());
    const std::string bytes = readFile(path, options.limits.maxFileBytes);
    guard.maxSideFileBytes =
        std::max(checkDeclaredSizes(bytes, ext == ".glb", path, options.limits), options.limits.maxImageBytes);
    return parseGuarded(bytes, ext == ".glb", path, baseDir, warnings, &guard);
}

}  // namespace shadelab::gltf
