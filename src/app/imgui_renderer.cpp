#include "imgui_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <imgui.h>

namespace psb::app {

namespace {

// ImGui packs a colour as IM_COL32 (its shifts say where each channel is); SDL_Color is bytes in
// r, g, b, a order. Unpacking by shift is right on either byte order.
SDL_Color unpack(ImU32 c) {
    return SDL_Color{static_cast<Uint8>((c >> IM_COL32_R_SHIFT) & 0xFF),
                     static_cast<Uint8>((c >> IM_COL32_G_SHIFT) & 0xFF),
                     static_cast<Uint8>((c >> IM_COL32_B_SHIFT) & 0xFF),
                     static_cast<Uint8>((c >> IM_COL32_A_SHIFT) & 0xFF)};
}

// A clip rectangle in target pixels, cut to the target; nullopt-like false when empty.
bool clipRect(const ImVec4& clip, ImVec2 origin, ImVec2 scale, int targetW, int targetH,
              SDL_Rect& out) {
    const float x0 = std::max(0.f, std::round((clip.x - origin.x) * scale.x));
    const float y0 = std::max(0.f, std::round((clip.y - origin.y) * scale.y));
    const float x1 =
        std::min(static_cast<float>(targetW), std::round((clip.z - origin.x) * scale.x));
    const float y1 =
        std::min(static_cast<float>(targetH), std::round((clip.w - origin.y) * scale.y));
    if (x1 <= x0 || y1 <= y0) return false;
    out = SDL_Rect{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0),
                   static_cast<int>(y1 - y0)};
    return true;
}

}  // namespace

ImGuiRenderer::ImGuiRenderer(SDL_Renderer* renderer) : renderer_(renderer) {
    if (renderer_ == nullptr) throw std::runtime_error("ImGuiRenderer: no SDL renderer");
    ImGuiIO& io = ImGui::GetIO();
    io.BackendRendererName = "particle-sandbox SDL_Renderer";
    // Draw lists past 65 536 vertices keep 16-bit indices, relative to each command's VtxOffset.
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    rebuildFontTexture();
}

ImGuiRenderer::~ImGuiRenderer() {
    destroyFontTexture();
}

void ImGuiRenderer::destroyFontTexture() {
    if (font_ == nullptr) return;
    if (ImGui::GetCurrentContext() != nullptr) ImGui::GetIO().Fonts->SetTexID(nullptr);
    SDL_DestroyTexture(font_);
    font_ = nullptr;
}

void ImGuiRenderer::rebuildFontTexture() {
    destroyFontTexture();
    ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    atlas.GetTexDataAsRGBA32(&pixels, &w, &h);
    font_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STATIC, w, h);
    if (font_ == nullptr || SDL_UpdateTexture(font_, nullptr, pixels, 4 * w) != 0 ||
        SDL_SetTextureBlendMode(font_, SDL_BLENDMODE_BLEND) != 0) {
        const std::string reason = SDL_GetError();
        destroyFontTexture();
        throw std::runtime_error("ImGuiRenderer: cannot make the " + std::to_string(w) + "x" +
                                 std::to_string(h) + " font texture: " + reason);
    }
    atlas.SetTexID(font_);
}

int ImGuiRenderer::render(const ImDrawData& data) {
    // With a render scale set by the caller SDL scales what it is given; otherwise ImGui's
    // points become target pixels here.
    float sdlScaleX = 1.f, sdlScaleY = 1.f;
    SDL_RenderGetScale(renderer_, &sdlScaleX, &sdlScaleY);
    const ImVec2 scale(sdlScaleX == 1.f ? data.FramebufferScale.x : 1.f,
                       sdlScaleY == 1.f ? data.FramebufferScale.y : 1.f);
    const int targetW = static_cast<int>(data.DisplaySize.x * scale.x);
    const int targetH = static_cast<int>(data.DisplaySize.y * scale.y);
    if (targetW <= 0 || targetH <= 0) return 0;  // minimised

    SDL_Rect oldViewport{}, oldClip{};
    const bool oldClipOn = SDL_RenderIsClipEnabled(renderer_) == SDL_TRUE;
    SDL_RenderGetViewport(renderer_, &oldViewport);
    SDL_RenderGetClipRect(renderer_, &oldClip);
    SDL_RenderSetViewport(renderer_, nullptr);

    int failures = 0;
    const ImVec2 origin = data.DisplayPos;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        vertices_.resize(static_cast<std::size_t>(list.VtxBuffer.Size));
        for (int i = 0; i < list.VtxBuffer.Size; ++i) {
            const ImDrawVert& v = list.VtxBuffer[i];
            vertices_[static_cast<std::size_t>(i)] =
                SDL_Vertex{{(v.pos.x - origin.x) * scale.x, (v.pos.y - origin.y) * scale.y},
                           unpack(v.col),
                           {v.uv.x, v.uv.y}};
        }
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            if (cmd.UserCallback != nullptr) {
                // ImDrawCallback_ResetRenderState asks for the state set above; there is no other.
                if (cmd.UserCallback != ImDrawCallback_ResetRenderState)
                    cmd.UserCallback(&list, &cmd);
                SDL_RenderSetViewport(renderer_, nullptr);
                continue;
            }
            if (cmd.ElemCount == 0) continue;
            SDL_Rect clip{};
            if (!clipRect(cmd.ClipRect, origin, scale, targetW, targetH, clip)) continue;
            SDL_RenderSetClipRect(renderer_, &clip);
            const SDL_Vertex* first = vertices_.data() + cmd.VtxOffset;
            const int count = list.VtxBuffer.Size - static_cast<int>(cmd.VtxOffset);
            const int rc = SDL_RenderGeometryRaw(
                renderer_, static_cast<SDL_Texture*>(cmd.GetTexID()), &first->position.x,
                sizeof(SDL_Vertex), &first->color, sizeof(SDL_Vertex), &first->tex_coord.x,
                sizeof(SDL_Vertex), count, list.IdxBuffer.Data + cmd.IdxOffset,
                static_cast<int>(cmd.ElemCount), sizeof(ImDrawIdx));
            failures += rc != 0;
        }
    }

    SDL_RenderSetViewport(renderer_, &oldViewport);
    SDL_RenderSetClipRect(renderer_, oldClipOn ? &oldClip : nullptr);
    return failures;
}

}  // namespace psb::app
