// PanelCache: which draw lists are the panel's, what they were drawn from, and the copies in and out.
#include "app/panel_cache.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace shadelab::app {
namespace {

template <typename T>
void append(std::vector<uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

void appendBytes(std::vector<uint8_t>& out, const void* data, size_t bytes) {
    const auto* p = static_cast<const uint8_t*>(data);
    out.insert(out.end(), p, p + bytes);
}

// Where a draw list's commands fall against the panel's columns [0, panelPixels).
enum class Side { Empty, Panel, Outside, Both };

Side sideOf(const ImDrawList& list, const ImDrawData& data, int panelPixels, ImTextureID font) {
    Side side = Side::Empty;
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
        if (cmd.UserCallback != nullptr) return Side::Both;  // state of its own: never kept
        if (cmd.ElemCount == 0) continue;
        // The columns it can touch: its triangles' extent within the backend's scissor (the clip rectangle), in
        // framebuffer pixels. Overlays over the image clip to the whole window, so their vertices say where they are.
        float v0 = cmd.ClipRect.z, v1 = cmd.ClipRect.x;
        for (unsigned k = 0; k < cmd.ElemCount; ++k) {
            const float x = list.VtxBuffer[int(cmd.VtxOffset + list.IdxBuffer[int(cmd.IdxOffset + k)])].pos.x;
            v0 = std::min(v0, x);
            v1 = std::max(v1, x);
        }
        const float x0 = (std::max(cmd.ClipRect.x, v0) - data.DisplayPos.x) * data.FramebufferScale.x;
        const float x1 = (std::min(cmd.ClipRect.z, v1) - data.DisplayPos.x) * data.FramebufferScale.x;
        if (x1 <= x0) continue;
        // A pixel is drawn when its centre (c + 0.5) is inside a triangle, and a centre on a right edge is not (GL's
        // rule). The panel's border reaches x = panelPixels + 0.5 (give or take float rounding), on the centre of the
        // image's first column, with its anti-aliasing fringe, whose outer vertices have alpha 0: a sliver past the
        // centre changes no 8-bit value (SHADELAB_PANEL_CACHE=verify, app_window_test, compares the pixels).
        const float edge = float(panelPixels) + 0.5f + 1.0f / 64.0f;
        const Side s = x1 <= edge ? Side::Panel : x0 > panelPixels - 0.5f ? Side::Outside : Side::Both;
        // Only the font atlas is known not to change: an image whose texture is redrawn would be kept stale.
        if (s == Side::Panel && cmd.TextureId != font) return Side::Both;
        if (side != Side::Empty && side != s) return Side::Both;
        side = s;
    }
    return side;
}

// Renders `lists` with the projection and scale of `whole`.
void draw(const ImDrawData& whole, std::vector<ImDrawList*>& lists) {
    if (lists.empty()) return;
    ImDrawData part = whole;
    part.CmdLists = lists.data();
    part.CmdListsCount = int(lists.size());
    part.TotalVtxCount = part.TotalIdxCount = 0;
    for (const ImDrawList* l : lists) {
        part.TotalVtxCount += l->VtxBuffer.Size;
        part.TotalIdxCount += l->IdxBuffer.Size;
    }
    ImGui_ImplOpenGL3_RenderDrawData(&part);
}

}  // namespace

PanelCache::Mode PanelCache::modeFromEnvironment() {
    const char* env = std::getenv("SHADELAB_PANEL_CACHE");
    const std::string v = env ? env : "";
    if (v == "off" || v == "0") return Mode::Off;
    if (v == "verify") return Mode::Verify;
    if (v == "verify-stale") return Mode::VerifyStale;
    return Mode::On;
}

void PanelCache::render(ImDrawData* data, int panelPixels, int fbWidth, int fbHeight) {
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);  // a multisampled window cannot be copied into pixel for pixel
    if (mode_ == Mode::Off || panelPixels <= 0 || samples > 0 || data == nullptr || !data->Valid) {
        ImGui_ImplOpenGL3_RenderDrawData(data);
        valid_ = false;
        ++counts_.whole;
        return;
    }
    const ImTextureID font = ImGui::GetIO().Fonts->TexID;
    std::vector<ImDrawList*> panel, outside;
    for (int i = 0; i < data->CmdListsCount; ++i) {
        ImDrawList* list = data->CmdLists[i];
        const Side side = sideOf(*list, *data, panelPixels, font);
        if (side == Side::Both) {
            ImGui_ImplOpenGL3_RenderDrawData(data);
            valid_ = false;
            ++counts_.whole;
            return;
        }
        if (side == Side::Panel) panel.push_back(list);
        if (side == Side::Outside) outside.push_back(list);
    }

    // What the panel's pixels are drawn from: the frame's geometry and every panel list's buffers and commands.
    next_.clear();
    for (const int v : {panelPixels, fbWidth, fbHeight}) append(next_, v);
    for (const float v : {data->DisplayPos.x, data->DisplayPos.y, data->DisplaySize.x, data->DisplaySize.y,
                          data->FramebufferScale.x, data->FramebufferScale.y})
        append(next_, v);
    for (const ImDrawList* l : panel) {
        append(next_, l->VtxBuffer.Size);
        appendBytes(next_, l->VtxBuffer.Data, size_t(l->VtxBuffer.Size) * sizeof(ImDrawVert));
        append(next_, l->IdxBuffer.Size);
        appendBytes(next_, l->IdxBuffer.Data, size_t(l->IdxBuffer.Size) * sizeof(ImDrawIdx));
        for (const ImDrawCmd& cmd : l->CmdBuffer) {
            for (const float v : {cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w}) append(next_, v);
            for (const unsigned v : {cmd.VtxOffset, cmd.IdxOffset, cmd.ElemCount}) append(next_, v);
        }
    }

    const bool sized = valid_ && width_ == panelPixels && height_ == fbHeight;
    const bool same = sized && next_ == signature_;
    const bool verify = mode_ == Mode::Verify || mode_ == Mode::VerifyStale;
    if (same || (sized && mode_ == Mode::VerifyStale)) {
        if (verify) {
            // The panel drawn as usual over its cleared background, then the kept pixels over it: the two compared.
            draw(*data, panel);
            const std::vector<uint8_t> drawn = readPanel(panelPixels, fbHeight);
            restore(panelPixels, fbHeight);
            ++counts_.verified;
            if (readPanel(panelPixels, fbHeight) != drawn) ++counts_.differing;
        } else {
            restore(panelPixels, fbHeight);
        }
        ++counts_.hits;
    } else {
        draw(*data, panel);
        keep(panelPixels, fbHeight);
        signature_.swap(next_);
        valid_ = true;
        ++counts_.misses;
    }
    draw(*data, outside);
}

void PanelCache::keep(int width, int height) {
    if (!texture_ || width != width_ || height != height_) {
        texture_ = gl::Texture::create();
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        if (!fbo_) fbo_ = gl::Framebuffer::create();
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        width_ = width;
        height_ = height;
    }
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PanelCache::restore(int width, int height) const {
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<uint8_t> PanelCache::readPanel(int width, int height) const {
    std::vector<uint8_t> pixels(size_t(width) * size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

}  // namespace shadelab::app
