#pragma once
#include <volume_model/TransferFunction.h>

#include <osg/ref_ptr>
#include <vector>

namespace volren {

/// Undo/redo for edits of one TransferFunction. It keeps snapshots, never a live copy:
/// the editor changes the model directly and calls record() after each finished edit.
class TransferFunctionHistory
{
public:
    /// Starts the history of `tf` with its current state.
    explicit TransferFunctionHistory(TransferFunction* tf);

    /// Remembers the current state of the TF as a new step (drops any redo steps).
    void record();
    /// Restores the previous step; false when there is none.
    bool undo();
    /// Re-applies the step undone last; false when there is none.
    bool redo();
    bool canUndo() const { return _current > 0; }                    ///< a step to undo exists
    bool canRedo() const { return _current + 1 < _steps.size(); }   ///< a step to redo exists

private:
    void restore(const TransferFunction& snapshot);

    osg::ref_ptr<TransferFunction> _tf;
    std::vector<osg::ref_ptr<TransferFunction>> _steps;
    std::size_t _current = 0;
};

}  // namespace volren
