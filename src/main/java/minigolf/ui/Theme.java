package minigolf.ui;

import imgui.ImGui;
import imgui.ImGuiStyle;
import imgui.flag.ImGuiCol;

/** A calm green-and-cream look for the menus and the HUD, readable over the course. */
final class Theme {
    private Theme() {
    }

    static void apply(float scale) {
        ImGui.styleColorsDark();
        ImGuiStyle s = ImGui.getStyle();
        s.setWindowRounding(8);
        s.setFrameRounding(5);
        s.setGrabRounding(5);
        s.setWindowPadding(14, 12);
        s.setFramePadding(10, 6);
        s.setItemSpacing(10, 8);
        s.scaleAllSizes(scale);
        s.setColor(ImGuiCol.WindowBg, 0.07f, 0.12f, 0.09f, 0.90f);
        s.setColor(ImGuiCol.TitleBgActive, 0.13f, 0.35f, 0.20f, 1f);
        s.setColor(ImGuiCol.TitleBg, 0.10f, 0.25f, 0.15f, 1f);
        s.setColor(ImGuiCol.Button, 0.18f, 0.45f, 0.26f, 1f);
        s.setColor(ImGuiCol.ButtonHovered, 0.25f, 0.58f, 0.33f, 1f);
        s.setColor(ImGuiCol.ButtonActive, 0.30f, 0.68f, 0.38f, 1f);
        s.setColor(ImGuiCol.FrameBg, 0.14f, 0.22f, 0.16f, 1f);
        s.setColor(ImGuiCol.Header, 0.18f, 0.45f, 0.26f, 0.8f);
        s.setColor(ImGuiCol.HeaderHovered, 0.25f, 0.58f, 0.33f, 0.9f);
        s.setColor(ImGuiCol.PlotHistogram, 0.90f, 0.70f, 0.20f, 1f);
        s.setColor(ImGuiCol.Text, 0.96f, 0.95f, 0.88f, 1f);
    }
}
