// The control panel's Video section: the format and area of a recording, Record / Stop (Ctrl+R),
// and where the last video went. The recording itself is the app's (platform/video_recorder.hpp);
// the panel shows what the frame loop reports of it (VideoStatus), never its own guess.

#include <array>
#include <cstddef>

#include <imgui.h>

#include "gui/control_panel.hpp"
#include "gui/widgets.hpp"
#include "session/session.hpp"

namespace psb::app {

using widgets::tip;

void ControlPanel::video(const Session& s, const VideoStatus& status) {
    const bool open = ImGui::CollapsingHeader("Video");
    mark("section Video");
    if (!open) return;
    VideoSettings settings = s.videoSettings();
    constexpr std::array<VideoFormat, 3> kFormats{VideoFormat::Mp4, VideoFormat::WebM,
                                                  VideoFormat::Gif};
    ImGui::BeginDisabled(status.recording);
    ImGui::SetNextItemWidth(90.f);
    if (ImGui::BeginCombo("##format", toString(settings.format))) {
        for (const VideoFormat f : kFormats) {
            if (ImGui::Selectable(toString(f), f == settings.format)) {
                settings.format = f;
                out_.emplace_back(cmd::SetVideoSettings{settings});
            }
        }
        ImGui::EndCombo();
    }
    mark("video format");
    tip("MP4 (H.264) plays in slides and everywhere; WebM (VP8) for web pages; GIF for slides, "
        "25 frames a second, at most 640 pixels wide");
    widgets::sameLineIfRoom(widgets::checkWidth("with the panel"));
    bool withPanel = settings.withPanel;
    if (ImGui::Checkbox("with the panel", &withPanel)) {
        settings.withPanel = withPanel;
        out_.emplace_back(cmd::SetVideoSettings{settings});
    }
    mark("video with panel");
    tip("Record the whole window, this panel included; otherwise the box's side of it");
    ImGui::EndDisabled();

    const std::string& problem = status.unavailable[static_cast<std::size_t>(settings.format)];
    ImGui::BeginDisabled(!status.recording && !problem.empty());
    if (widgets::stateButton("Record video", status.recording ? "Stop video" : "Record video")) {
        out_.emplace_back(cmd::ToggleVideo{});
    }
    ImGui::EndDisabled();
    mark("Record video");
    tip(("Record what the window shows, at its frame rate, into " + s.exportDir().string() +
         " (Ctrl+R); again: stop and save")
            .c_str());
    if (status.recording) {
        ImGui::SameLine();
        ImGui::TextColored(widgets::problem(s.view().theme), "REC %d:%02d, %zu frames",
                           static_cast<int>(status.seconds) / 60,
                           static_cast<int>(status.seconds) % 60, status.frames);
        if (status.dropped > 0) {
            ImGui::TextWrapped("%zu frames left out: the encoder is behind", status.dropped);
        }
    } else if (!problem.empty()) {
        ImGui::TextWrapped("Cannot record %s: %s", toString(settings.format), problem.c_str());
    } else if (!status.lastFile.empty()) {
        ImGui::TextWrapped("Saved %s", status.lastFile.c_str());
    }
}

}  // namespace psb::app
