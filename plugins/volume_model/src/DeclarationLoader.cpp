#include <volume_model/DeclarationLoader.h>

namespace volren {

namespace {

std::function<void()>& loaderSlot()
{
    static std::function<void()> loader;
    return loader;
}

}  // namespace

void setDeclarationLoader(std::function<void()> loader) { loaderSlot() = std::move(loader); }

void loadDeclarations()
{
    std::function<void()>& slot = loaderSlot();
    if (!slot) return;
    const std::function<void()> loader = std::move(slot);
    slot = nullptr;  // once
    loader();
}

}  // namespace volren
