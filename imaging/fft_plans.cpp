#include "imaging/fft_plans.h"

#include <fftw3.h>

#include <map>
#include <mutex>
#include <utility>

namespace imaging {
namespace {

struct PlanPair {
    fftwf_plan forward = nullptr;
    fftwf_plan inverse = nullptr;
};

std::mutex& planMutex()
{
    static std::mutex m;
    return m;
}

// Plans are made with FFTW_ESTIMATE: measuring would take longer than the
// registrations of a whole scan, and a plan made once per tile size is reused.
const PlanPair& plansFor(int width, int height)
{
    static std::map<std::pair<int, int>, PlanPair> cache;
    std::lock_guard<std::mutex> lock(planMutex());
    auto it = cache.find({width, height});
    if (it != cache.end())
        return it->second;
    const std::size_t real = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    const std::size_t spectrum = static_cast<std::size_t>(height) * static_cast<std::size_t>(width / 2 + 1);
    float* r = fftwf_alloc_real(real);
    fftwf_complex* c = fftwf_alloc_complex(spectrum);
    PlanPair p;
    p.forward = fftwf_plan_dft_r2c_2d(height, width, r, c, FFTW_ESTIMATE);
    p.inverse = fftwf_plan_dft_c2r_2d(height, width, c, r, FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
    fftwf_free(r);
    fftwf_free(c);
    return cache.emplace(std::make_pair(width, height), p).first->second;
}

} // namespace

void FftFree::operator()(void* p) const
{
    fftwf_free(p);
}

FloatBuffer fftFloats(std::size_t n)
{
    return FloatBuffer(fftwf_alloc_real(n));
}

ComplexBuffer fftComplex(std::size_t n)
{
    return ComplexBuffer(reinterpret_cast<std::complex<float>*>(fftwf_alloc_complex(n)));
}

void forwardFft(int width, int height, float* in, std::complex<float>* out)
{
    fftwf_execute_dft_r2c(plansFor(width, height).forward, in, reinterpret_cast<fftwf_complex*>(out));
}

void inverseFft(int width, int height, std::complex<float>* in, float* out)
{
    fftwf_execute_dft_c2r(plansFor(width, height).inverse, reinterpret_cast<fftwf_complex*>(in), out);
}

int fastFftSize(int limit)
{
    for (int n = limit; n > 1; --n) {
        int m = n;
        for (int f : {2, 3, 5, 7})
            while (m % f == 0)
                m /= f;
        if (m == 1)
            return n;
    }
    return 1;
}

} // namespace imaging
