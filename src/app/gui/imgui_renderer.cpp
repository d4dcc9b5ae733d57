#include "gui/imgui_renderer.hpp"

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

bool sameColor(const SDL_Color& a, const SDL_Color& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

bool isWhole(float v) {
    return v == std::floor(v);
}

// The two triangles (a, b, c), (a, c, d) ImGui's PrimRect and PrimRectUV make for an
// axis-aligned rectangle of one colour (backgrounds, frames, glyphs, images): a at the top left,
// b top right, c bottom right, d bottom left. Only rectangles on whole pixels are taken, so a
// rectangle fill covers exactly the pixels the triangles would. Returns the a and c vertices.
bool rectAt(const SDL_Vertex* v, const ImDrawIdx* i, const SDL_Vertex*& a, const SDL_Vertex*& c) {
    if (i[3] != i[0] || i[4] != i[2]) return false;
    const SDL_Vertex &va = v[i[0]], &vb = v[i[1]], &vc = v[i[2]], &vd = v[i[5]];
    const SDL_FPoint &pa = va.position, &pb = vb.position, &pc = vc.position, &pd = vd.position;
    if (pa.y != pb.y || pb.x != pc.x || pc.y != pd.y || pd.x != pa.x) return false;
    if (!(pa.x < pc.x && pa.y < pc.y)) return false;
    if (!isWhole(pa.x) || !isWhole(pa.y) || !isWhole(pc.x) || !isWhole(pc.y)) return false;
    if (!sameColor(va.color, vb.color) || !sameColor(va.color, vc.color) ||
        !sameColor(va.color, vd.color)) {
        return false;
    }
    const SDL_FPoint &ta = va.tex_coord, &tb = vb.tex_coord, &tc = vc.tex_coord, &td = vd.tex_coord;
    if (ta.y != tb.y || tb.x != tc.x || tc.y != td.y || td.x != ta.x) return false;
    a = &va;
    c = &vc;
    return true;
}

// `uv` × `size` when that is a whole number of texels (to rounding), else -1.
int texel(float uv, int size) {
    const float t = uv * static_cast<float>(size);
    const float r = std::round(t);
    return std::abs(t - r) < 1e-3f ? static_cast<int>(r) : -1;
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
    white_ = SDL_FPoint{atlas.TexUvWhitePixel.x, atlas.TexUvWhitePixel.y};
    fontW_ = w;
    fontH_ = h;
}

bool ImGuiRenderer::drawRect(const SDL_Vertex& topLeft, const SDL_Vertex& bottomRight,
                             SDL_Texture* texture) {
    const SDL_Color& c = topLeft.color;
    const SDL_FPoint &p0 = topLeft.position, &p1 = bottomRight.position;
    const SDL_Rect dst{static_cast<int>(p0.x), static_cast<int>(p0.y),
                       static_cast<int>(p1.x - p0.x), static_cast<int>(p1.y - p0.y)};
    const SDL_FPoint &t0 = topLeft.tex_coord, &t1 = bottomRight.tex_coord;
    if (texture == font_ && t0.x == white_.x && t0.y == white_.y && t1.x == white_.x &&
        t1.y == white_.y) {
        // An opaque fill is a copy of the colour; blending it would give the same pixels at
        // several times the cost in SDL's software renderer.
        SDL_SetRenderDrawBlendMode(renderer_,
                                   c.a == 255 ? SDL_BLENDMODE_NONE : SDL_BLENDMODE_BLEND);
        SDL_SetRenderDrawColor(renderer_, c.r, c.g, c.b, c.a);
        return SDL_RenderFillRect(renderer_, &dst) == 0;
    }
    if (texture == nullptr) return false;
    int w = fontW_, h = fontH_;
    if (texture != font_ && SDL_QueryTexture(texture, nullptr, nullptr, &w, &h) != 0) return false;
    const int x0 = texel(t0.x, w), y0 = texel(t0.y, h), x1 = texel(t1.x, w), y1 = texel(t1.y, h);
    // Only an unscaled copy: SDL's scaled copy would sample differently from the geometry.
    if (x0 < 0 || y0 < 0 || x1 - x0 != dst.w || y1 - y0 != dst.h) return false;
    const SDL_Rect src{x0, y0, dst.w, dst.h};
    Uint8 r = 255, g = 255, b = 255, a = 255;
    SDL_GetTextureColorMod(texture, &r, &g, &b);
    SDL_GetTextureAlphaMod(texture, &a);
    SDL_SetTextureColorMod(texture, c.r, c.g, c.b);
    SDL_SetTextureAlphaMod(texture, c.a);
    const bool ok = SDL_RenderCopy(renderer_, texture, &src, &dst) == 0;
    SDL_SetTextureColorMod(texture, r, g, b);
    SDL_SetTextureAlphaMod(texture, a);
    return ok;
}

int ImGuiRenderer::drawCommand(const SDL_Vertex* vertices, int count, const ImDrawIdx* indices,
                               std::size_t n, SDL_Texture* texture) {
    int failures = 0;
    const auto geometry = [&](std::size_t from, std::size_t to) {
        if (to == from) return;
        failures +=
            SDL_RenderGeometryRaw(renderer_, texture, &vertices->position.x, sizeof(SDL_Vertex),
                                  &vertices->color, sizeof(SDL_Vertex), &vertices->tex_coord.x,
                                  sizeof(SDL_Vertex), count, indices + from,
                                  static_cast<int>(to - from), sizeof(ImDrawIdx)) != 0;
    };
    // Rectangles (a panel's background, frames, glyphs) are filled or copied as rectangles, the
    // rest drawn as triangles, in ImGui's order: SDL's software renderer blends a textured
    // triangle pixel by pixel, and an opaque background then costs as much as the rest.
    std::size_t pending = 0, k = 0;
    while (k + 6 <= n) {
        const SDL_Vertex *a = nullptr, *c = nullptr;
        if (rectAt(vertices, indices + k, a, c)) {
            geometry(pending, k);
            if (!drawRect(*a, *c, texture)) geometry(k, k + 6);
            k += 6;
            pending = k;
        } else {
            k += 3;
        }
    }
    geometry(pending, n);
    return failures;
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
    Uint8 oldR = 0, oldG = 0, oldB = 0, oldA = 0;
    SDL_BlendMode oldBlend = SDL_BLENDMODE_NONE;
    SDL_GetRenderDrawColor(renderer_, &oldR, &oldG, &oldB, &oldA);
    SDL_GetRenderDrawBlendMode(renderer_, &oldBlend);
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
            failures += drawCommand(vertices_.data() + cmd.VtxOffset,
                                    list.VtxBuffer.Size - static_cast<int>(cmd.VtxOffset),
                                    list.IdxBuffer.Data + cmd.IdxOffset, cmd.ElemCount,
                                    static_cast<SDL_Texture*>(cmd.GetTexID()));
        }
    }

    SDL_RenderSetViewport(renderer_, &oldViewport);
    SDL_RenderSetClipRect(renderer_, oldClipOn ? &oldClip : nullptr);
    SDL_SetRenderDrawColor(renderer_, oldR, oldG, oldB, oldA);
    SDL_SetRenderDrawBlendMode(renderer_, oldBlend);
    return failures;
}

}  // namespace psb::app
