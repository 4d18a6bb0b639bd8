#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dev::proto {

/// Little-endian writer into a growing buffer.
class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : m_out(out) {}
    void u8(std::uint8_t v) { m_out.push_back(v); }
    void u16(std::uint16_t v) { raw(v, 2); }
    void u32(std::uint32_t v) { raw(v, 4); }
    void u64(std::uint64_t v) { raw(v, 8); }
    void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
    void f64(double v)
    {
        std::uint64_t u;
        std::memcpy(&u, &v, sizeof u);
        u64(u);
    }
    /// Short string: u8 length then bytes, cut to at most 255 bytes. The cut
    /// never splits a UTF-8 sequence (messages carry "µL", "×", "…").
    void str(const std::string& s)
    {
        std::size_t n = s.size();
        if (n > 255) {
            n = 255;
            while (n > 0 && (static_cast<unsigned char>(s[n]) & 0xC0) == 0x80)
                --n;  // s[n] continues a sequence: cut before the sequence starts
        }
        u8(static_cast<std::uint8_t>(n));
        m_out.insert(m_out.end(), s.begin(), s.begin() + static_cast<std::ptrdiff_t>(n));
    }

private:
    void raw(std::uint64_t v, int bytes)
    {
        for (int i = 0; i < bytes; ++i)
            m_out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    std::vector<std::uint8_t>& m_out;
};

/// Little-endian reader that never reads past the end: a short read sets
/// `ok()` false and yields zeros, so decoders check once at the end.
class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
    explicit ByteReader(const std::vector<std::uint8_t>& v) : ByteReader(v.data(), v.size()) {}
    std::uint8_t u8() { return static_cast<std::uint8_t>(raw(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(raw(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(raw(4)); }
    std::uint64_t u64() { return raw(8); }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    double f64()
    {
        const std::uint64_t u = u64();
        double v;
        std::memcpy(&v, &u, sizeof v);
        return v;
    }
    std::string str()
    {
        const std::size_t n = u8();
        if (!m_ok || m_pos + n > m_size) {
            m_ok = false;
            return {};
        }
        std::string s(reinterpret_cast<const char*>(m_data + m_pos), n);
        m_pos += n;
        return s;
    }
    bool ok() const { return m_ok; }
    /// True when every byte was consumed and no read ran short.
    bool done() const { return m_ok && m_pos == m_size; }
    std::size_t remaining() const { return m_ok ? m_size - m_pos : 0; }

private:
    std::uint64_t raw(int bytes)
    {
        if (!m_ok || m_pos + static_cast<std::size_t>(bytes) > m_size) {
            m_ok = false;
            return 0;
        }
        std::uint64_t v = 0;
        for (int i = 0; i < bytes; ++i)
            v |= static_cast<std::uint64_t>(m_data[m_pos + static_cast<std::size_t>(i)]) << (8 * i);
        m_pos += static_cast<std::size_t>(bytes);
        return v;
    }
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_pos = 0;
    bool m_ok = true;
};

/// A decoded message when its reader used every byte of the payload, else nothing:
/// a payload longer than its type is malformed, not padded.
template <typename T>
std::optional<T> finish(const ByteReader& r, T&& value)
{
    if (!r.done())
        return std::nullopt;
    return std::optional<T>(std::forward<T>(value));
}

} // namespace dev::proto
