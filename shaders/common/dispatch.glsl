// A kernel's place in a 1-D dispatch. ComputePipeline::dispatch folds a dispatch wider than the
// device allows (maxComputeWorkGroupCount[0]: 65535 on lavapipe, AMD and Intel; a 2048x2048
// image needs 65536 workgroups of 64 pixels) into rows of workgroups; these undo the fold.
// The last row may hold workgroups past the requested count: every kernel checks its index.
#ifndef HIPR_DISPATCH_GLSL
#define HIPR_DISPATCH_GLSL

uint dispatch_group() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

// For one-dimensional workgroups (local_size_x only).
uint dispatch_index() { return dispatch_group() * gl_WorkGroupSize.x + gl_LocalInvocationIndex; }

#endif
