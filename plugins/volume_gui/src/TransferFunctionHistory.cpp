#include <volume_gui/TransferFunctionHistory.h>

namespace volren {

TransferFunctionHistory::TransferFunctionHistory(TransferFunction* tf) : _tf(tf)
{
    _steps.push_back(new TransferFunction(*tf));
}

void TransferFunctionHistory::record()
{
    _steps.resize(_current + 1);
    _steps.push_back(new TransferFunction(*_tf));
    _current = _steps.size() - 1;
}

bool TransferFunctionHistory::undo()
{
    if (!canUndo()) return false;
    restore(*_steps[--_current]);
    return true;
}

bool TransferFunctionHistory::redo()
{
    if (!canRedo()) return false;
    restore(*_steps[++_current]);
    return true;
}

void TransferFunctionHistory::restore(const TransferFunction& snapshot)
{
    _tf->assign(snapshot);  // edit the live model in place: every node sharing it sees the change
}

}  // namespace volren
