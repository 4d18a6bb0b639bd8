#include "device/camera/frame.h"

namespace dev::camera {

int bytesPerPixel(PixelFormat format)
{
    switch (format) {
    case PixelFormat::Grey8: return 1;
    case PixelFormat::Grey16: return 2;
    case PixelFormat::Rgb8: return 3;
    }
    return 1;
}

} // namespace dev::camera
