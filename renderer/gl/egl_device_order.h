#pragma once
// On a farm node with several GPUs the scheduler assigns one to each job through
// CUDA_VISIBLE_DEVICES (Slurm's --gres=gpu, Kubernetes' device plugin). EGL enumerates every GPU
// regardless, so the headless context puts the assigned one first.
#include <epoxy/egl.h>

#include <optional>
#include <string>
#include <vector>

namespace glint::gl {

// The first CUDA device index in a CUDA_VISIBLE_DEVICES value ("2,3" -> 2); nullopt when unset,
// empty, "NoDevFiles" or a GPU UUID (which EGL cannot be matched against without NVML).
std::optional<int> assignedCudaDevice(const char* cudaVisibleDevices);

// `devices` reordered so that the one whose EGL_CUDA_DEVICE_NV is `cudaDevice` comes first
// (unchanged when no device reports that index).
std::vector<EGLDeviceEXT> assignedDeviceFirst(std::vector<EGLDeviceEXT> devices, std::optional<int> cudaDevice);

} // namespace glint::gl
