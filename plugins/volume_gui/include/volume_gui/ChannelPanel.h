#pragma once
#include <volume_gui/TransferFunctionEditor.h>

#include <volume_model/VolumeNode.h>

#include <osg/Vec3>

#include <memory>
#include <vector>

namespace volren {

/// The channels of one multi-channel VolumeNode as an ImGui window ("Channels"): per channel
/// whether it shows, its colour and display window (the microscopy way: the channel's transfer
/// function becomes that colour with opacity rising over the window), its opacity scale, and
/// which channel the transfer-function editor edits. Each channel has its own editor over that
/// channel's histogram, with its own undo/redo; a colour or window change is one undo step of it.
class ChannelPanel
{
public:
    /// Edits the channels of `node` (a channel without a transfer function of its own gets a copy
    /// of the node's on its first edit).
    explicit ChannelPanel(VolumeNode* node);

    /// Draws the window and the selected channel's editor into the current ImGui frame and
    /// applies this frame's changes (nothing for a node without a volume).
    void draw();

    /// Channels of the node's volume.
    int channels() const;
    /// The channel the editor edits (from 0).
    int selected() const { return _selected; }
    /// Makes the editor edit channel `c`; throws std::out_of_range when there is none.
    void select(int c);
    /// The editor of the selected channel: its transfer function over its histogram (the shown
    /// time point's block).
    TransferFunctionEditor& editor();

    /// A channel's colour and window as the panel shows them.
    struct ColourWindow
    {
        osg::Vec3 colour{1, 1, 1};
        double low = 0.0, high = 1.0;  ///< data values
        double opacity = 1.0;          ///< the transfer function's opacity at the window's top
    };
    /// Channel `c`'s colour and window, read from its transfer function: the colour of its last
    /// point, the window from its last transparent point to its first point of full opacity.
    ColourWindow colourWindow(int c) const;
    /// Rewrites channel `c`'s transfer function as colourWindowTransferFunction(`cw`), recorded
    /// as one undo step of its editor when `record` (a drag records once, when it ends). Throws
    /// std::out_of_range when there is no channel `c`, and std::invalid_argument unless
    /// low < high and 0 <= opacity <= 1.
    void setColourWindow(int c, const ColourWindow& cw, bool record = true);

private:
    TransferFunction* ownTransferFunction(int c);

    osg::ref_ptr<VolumeNode> _node;
    int _selected = 0;
    std::vector<std::unique_ptr<TransferFunctionEditor>> _editors;  ///< per channel, made when first shown
    std::vector<bool> _dragging;  ///< per channel: a colour or window drag changed its TF, not yet recorded
};

}  // namespace volren
