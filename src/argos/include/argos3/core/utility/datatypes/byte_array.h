// ARGoS's CByteArray (argos3/core/utility/datatypes/byte_array.h): the bytes a
// range-and-bearing packet carries. Integers go in and out in network byte order (big
// endian), as ARGoS's; strings end with a 0 byte. essaim leaves out ARGoS's double and float
// encoding (no controller of the census sends one): writing a floating-point value does not
// compile.
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>

#include <cstddef>
#include <cstring>
#include <iterator>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace argos {

class CByteArray {
 public:
  CByteArray() {}
  CByteArray(const UInt8* pun_buffer, size_t un_size) : m_vecBuffer(pun_buffer, pun_buffer + un_size) {}
  explicit CByteArray(size_t un_size, UInt8 un_value = 0) : m_vecBuffer(un_size, un_value) {}
  size_t Size() const { return m_vecBuffer.size(); }
  void Resize(size_t un_size, UInt8 un_value = 0) { m_vecBuffer.resize(un_size, un_value); }
  void Swap(CByteArray& c_other) { m_vecBuffer.swap(c_other.m_vecBuffer); }
  bool Empty() const { return m_vecBuffer.empty(); }
  const UInt8* ToCArray() const { return Empty() ? nullptr : m_vecBuffer.data(); }
  UInt8* ToCArray() { return Empty() ? nullptr : m_vecBuffer.data(); }
  void Clear() { m_vecBuffer.clear(); }
  void Zero() { std::fill(m_vecBuffer.begin(), m_vecBuffer.end(), 0); }
  /// Copies `un_size` bytes in, keeping this array's storage when it is large enough.
  void Assign(const UInt8* pun_buffer, size_t un_size) { m_vecBuffer.assign(pun_buffer, pun_buffer + un_size); }
  /// Checked, as ARGoS's: an index past the end throws.
  UInt8& operator[](size_t un_index) {
    CheckIndex(un_index);
    return m_vecBuffer[un_index];
  }
  UInt8 operator[](size_t un_index) const {
    CheckIndex(un_index);
    return m_vecBuffer[un_index];
  }
  bool operator==(const CByteArray& c_other) const { return m_vecBuffer == c_other.m_vecBuffer; }
  bool operator!=(const CByteArray& c_other) const { return !(*this == c_other); }
  CByteArray& AddBuffer(const UInt8* pun_buffer, size_t un_size) {
    m_vecBuffer.insert(m_vecBuffer.end(), pun_buffer, pun_buffer + un_size);
    return *this;
  }
  CByteArray& FetchBuffer(UInt8* pun_buffer, size_t un_size) {
    CheckAvailable(un_size);
    std::memcpy(pun_buffer, m_vecBuffer.data(), un_size);
    m_vecBuffer.erase(m_vecBuffer.begin(), m_vecBuffer.begin() + static_cast<std::ptrdiff_t>(un_size));
    return *this;
  }
  /// Removes a T from the front (`>>`): `UInt32 i = PopFront<UInt32>()`.
  template <typename T>
  T PopFront() {
    T tValue{};
    *this >> tValue;
    return tValue;
  }

  /// Appends an integer of any width, most significant byte first.
  template <typename T, typename = std::enable_if_t<std::is_integral<T>::value>>
  CByteArray& operator<<(T t_value) {
    using U = std::make_unsigned_t<T>;
    const U unValue = static_cast<U>(t_value);
    for (size_t i = sizeof(T); i-- > 0;) m_vecBuffer.push_back(static_cast<UInt8>(unValue >> (8 * i)));
    return *this;
  }
  /// Removes an integer from the front, most significant byte first.
  template <typename T, typename = std::enable_if_t<std::is_integral<T>::value>>
  CByteArray& operator>>(T& t_value) {
    using U = std::make_unsigned_t<T>;
    CheckAvailable(sizeof(T));
    U unValue = 0;
    for (size_t i = 0; i < sizeof(T); ++i) unValue = static_cast<U>((unValue << 8) | m_vecBuffer[i]);
    m_vecBuffer.erase(m_vecBuffer.begin(), m_vecBuffer.begin() + sizeof(T));
    t_value = static_cast<T>(unValue);
    return *this;
  }
  CByteArray& operator<<(const std::string& str_value) {
    m_vecBuffer.insert(m_vecBuffer.end(), str_value.begin(), str_value.end());
    m_vecBuffer.push_back(0);
    return *this;
  }
  CByteArray& operator<<(const char* str_value) { return *this << std::string(str_value); }
  /// Up to (and without) the first 0 byte, which is removed too.
  CByteArray& operator>>(std::string& str_value) {
    if (Empty()) THROW_ARGOSEXCEPTION("Attempting to extract values from empty byte array");
    size_t i = 0;
    while (i < Size() && m_vecBuffer[i] != 0) ++i;
    str_value.assign(m_vecBuffer.begin(), m_vecBuffer.begin() + static_cast<std::ptrdiff_t>(i));
    m_vecBuffer.erase(m_vecBuffer.begin(), m_vecBuffer.begin() + static_cast<std::ptrdiff_t>(i < Size() ? i + 1 : i));
    return *this;
  }
  /// "CByteArray [ b0 b1 ... ]" with each byte as a number (ARGoS writes them as characters).
  friend std::ostream& operator<<(std::ostream& c_os, const CByteArray& c_array) {
    c_os << "CByteArray [";
    for (UInt8 unByte : c_array.m_vecBuffer) c_os << " " << static_cast<unsigned>(unByte);
    return c_os << " ]" << std::endl;
  }

 private:
  void CheckIndex(size_t un_index) const {
    if (un_index >= Size())
      THROW_ARGOSEXCEPTION("CByteArray: index out of bounds [index = " << un_index << ", size=" << Size() << "]");
  }
  void CheckAvailable(size_t un_size) const {
    if (Size() < un_size)
      THROW_ARGOSEXCEPTION("Attempting to extract too many bytes from byte array (" << un_size << " requested, "
                                                                                    << Size() << " available)");
  }
  std::vector<UInt8> m_vecBuffer;
};

}  // namespace argos
