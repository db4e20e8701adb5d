#pragma once
#include <functional>

namespace volren {

/// The implementations' declarations (their parameters, their reference models) are made by the
/// renderer's registry as it registers them; the model's catalogs of them ask for them through
/// this hook at their first look-up, so that model code never names the renderer.
void setDeclarationLoader(std::function<void()> loader);
/// Runs the loader once (nothing without one; declarations made while it runs do not recurse).
void loadDeclarations();

}  // namespace volren
