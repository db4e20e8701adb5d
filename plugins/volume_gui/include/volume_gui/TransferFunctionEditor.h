#pragma once
#include <volume_gui/TransferFunctionHistory.h>

#include <volume_model/TransferFunction.h>
#include <volume_model/Volume.h>

#include <imgui.h>

#include <string>

namespace volren {

/// The transfer-function editor, drawn with Dear ImGui into the current ImGui frame. It edits
/// the model's TransferFunction in place (the renderer sees the modified count): control points
/// over the volume's histogram, one curve per channel or a colour map, a logarithmic opacity
/// axis, a zoomable value window, presets, undo/redo, and atomic load/save of `.tf` files.
/// Mouse: left-click on empty canvas adds a point and drags it, left-drag moves a point (value
/// and the active channel's level, never past its neighbours), right-click deletes one;
/// Ctrl+Z / Ctrl+Y undo and redo. Every finished edit is one undo step.
class TransferFunctionEditor
{
public:
    /// What the canvas edits: one channel's curve, or the colour map (opacity curve whose points
    /// carry their colour, picked for the selected point).
    enum class Channel { ColourMap, Red, Green, Blue, Alpha };

    /// Edits `tf`; `volume` (optional) supplies the histogram and the data range.
    TransferFunctionEditor(TransferFunction* tf, const Volume* volume = nullptr);

    /// Draws the editor window ("Transfer function") and applies this frame's input.
    void draw();

    Channel channel = Channel::ColourMap;  ///< the curve the mouse edits
    bool logHistogram = true;               ///< histogram bar heights on a log scale
    bool logOpacity = false;                ///< opacity axis logarithmic (1e-4 .. 1)
    double viewMin = 0.0, viewMax = 1.0;    ///< the value range the canvas shows (zoom)
    std::string path = "transfer-function.tf";  ///< file for Load / Save

    /// Screen position of a point of `value` whose active-channel level is `level`, in the
    /// canvas of the last draw() (for tests that drive the mouse).
    ImVec2 screenPosition(double value, double level) const;
    /// Data value and active-channel level under screen position `p` (last draw()'s canvas).
    std::pair<double, double> valueAt(const ImVec2& p) const;

    /// The volume whose histogram the editor shows (null: none).
    const Volume* volume() const { return _volume.get(); }
    /// The undo/redo steps of the edited TF.
    TransferFunctionHistory& history() { return _history; }
    /// Saves to `path` (temporary file + rename); false with `error` set on failure.
    bool save(std::string& error);
    /// Loads `path` into the edited TF (one undo step); false with `error` set on failure.
    bool load(std::string& error);
    /// Replaces the points with preset `name` spread over the TF's value window (one undo step);
    /// false when there is no such preset.
    bool applyPreset(const std::string& name);
    /// Names of the built-in presets.
    static const std::vector<std::string>& presetNames();
    /// Last message of load/save (error or success), shown under the buttons.
    const std::string& message() const { return _message; }

private:
    double levelOf(const osg::Vec4& rgba) const;
    void setLevel(osg::Vec4& rgba, double level) const;
    double toAxis(double level) const;
    double fromAxis(double axis) const;
    void drawCanvas();
    void drawToolbar();
    void drawFileRow();
    void handleMouse();

    osg::ref_ptr<TransferFunction> _tf;
    osg::ref_ptr<const Volume> _volume;
    TransferFunctionHistory _history;
    ImVec2 _canvasMin{0, 0}, _canvasMax{1, 1};
    bool _dragging = false;
    double _dragValue = 0.0;  ///< value of the point being dragged
    bool _haveSelection = false;
    double _selected = 0.0;  ///< value of the selected point
    std::string _message;
};

}  // namespace volren
