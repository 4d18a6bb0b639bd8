#pragma once
// What a host needs of a simulated device on a serial line, whatever protocol it speaks:
// bytes in, virtual time advanced by the host, bytes out. dev::sim::Firmware (the BenchPilot
// protocol) and dev::sim::GrblFirmware (GRBL 1.1 / grblHAL) both are one, so the pty host and the
// in-process link run either.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dev::sim {

class SerialDevice {
public:
    virtual ~SerialDevice() = default;
    /// Bytes from the host, in any chunking.
    virtual void receive(const std::uint8_t* data, std::size_t size) = 0;
    /// Runs the device for `dtS` of virtual time.
    virtual void advance(double dtS) = 0;
    /// Moves the bytes the device has sent since the last call to `out`.
    virtual void drainOutput(std::vector<std::uint8_t>& out) = 0;
    /// A host opened the port (where the transport can tell: Transport::peerOpened). A board
    /// wired to restart then (an Arduino's DTR line) restarts; the others do nothing.
    virtual void portOpened() {}
};

} // namespace dev::sim
