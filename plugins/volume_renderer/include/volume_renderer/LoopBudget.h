#pragma once
// What a driver lets one pixel's shader loop: Mesa's llvmpipe ends every loop of an invocation
// once all its loops together have run 65,535 iterations (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS,
// "shared between every loop"), so a longer march stops short and the image darkens or vanishes
// without an error. The pass refuses marches that cannot fit and coarsens the ones it may.

namespace volren {

struct BindContext;

/// Loop iterations one shader invocation may run, all its loops together, on the recorded
/// driver (GraphicsDriver.h): 65,535 on llvmpipe, 0 where no limit is known.
long loopIterationLimit();

/// Samples one view ray may take through the box being bound, at most: its diagonal over the
/// context's step, and the one sample after it.
double viewSamplesPerRay(const BindContext& context);

/// Whether the view ray through the box being bound keeps within loopIterationLimit(): its
/// samples times the iterations the chosen implementations declare per sample
/// (ShaderFunction::loops), with a margin for the loops they do not declare.
bool viewRayWithinLoopLimit(const BindContext& context);

/// Throws, naming the volume, its step and the limit, when the view ray may take more loop
/// iterations than loopIterationLimit() allows (its tail would be cut off): its samples times
/// the iterations the chosen implementations declare per sample (ShaderFunction::loops).
void checkViewRayWithinLoopLimit(const BindContext& context);

/// The step of a shadow march per lit sample towards each light, `step` or longer: the
/// longest step the march then takes with every view sample and light within the loop limit.
/// Throws when even one shadow step per sample and light does not fit; warns once per volume
/// and step where it lengthens the step.
double shadowStepWithinLoopLimit(const BindContext& context, double step);

}  // namespace volren
