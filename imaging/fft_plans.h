#pragma once
// FFTW plans cached per transform size. Making a plan is not thread-safe in FFTW
// (only executing one is), so plans are made under one mutex and kept for the life
// of the program; any thread may then execute them on its own aligned buffers
// (fftwf_execute_dft_r2c/c2r, the "new-array" interface).
#include <complex>
#include <cstddef>
#include <memory>

namespace imaging {

/// A buffer from fftwf_malloc (aligned as the cached plans expect), freed with fftwf_free.
struct FftFree {
    void operator()(void* p) const;
};
using FloatBuffer = std::unique_ptr<float[], FftFree>;
using ComplexBuffer = std::unique_ptr<std::complex<float>[], FftFree>;
FloatBuffer fftFloats(std::size_t n);
ComplexBuffer fftComplex(std::size_t n);

/// 2-D real transforms of `height` rows × `width` columns; the spectrum holds
/// height × (width / 2 + 1) values. The inverse is unnormalised (× width × height).
void forwardFft(int width, int height, float* in, std::complex<float>* out);
void inverseFft(int width, int height, std::complex<float>* in, float* out);

/// The largest n ≤ `limit` whose only prime factors are 2, 3, 5 and 7 (FFTW's fast sizes).
int fastFftSize(int limit);

} // namespace imaging
