// ARGoS's CQuaternion (argos3/core/utility/math/quaternion.h): orientations. essaim is
// planar, so what reaches the world of an orientation is its rotation about z.
#pragma once
#include <argos3/core/utility/math/vector3.h>

#include <cmath>
#include <ostream>

namespace argos {

class CQuaternion {
 public:
  CQuaternion() = default;
  CQuaternion(Real f_w, Real f_x, Real f_y, Real f_z) : m_fW(f_w), m_fX(f_x), m_fY(f_y), m_fZ(f_z) {}
  CQuaternion(const CRadians& c_angle, const CVector3& c_axis) { FromAngleAxis(c_angle, c_axis); }
  Real GetW() const { return m_fW; }
  Real GetX() const { return m_fX; }
  Real GetY() const { return m_fY; }
  Real GetZ() const { return m_fZ; }
  CQuaternion& FromAngleAxis(const CRadians& c_angle, const CVector3& c_axis) {
    const Real s = std::sin(c_angle.GetValue() / 2);
    m_fW = std::cos(c_angle.GetValue() / 2);
    m_fX = c_axis.GetX() * s, m_fY = c_axis.GetY() * s, m_fZ = c_axis.GetZ() * s;
    return *this;
  }
  /// Rotations about z, then y, then x (ARGoS's order of arguments).
  CQuaternion& FromEulerAngles(const CRadians& c_z, const CRadians& c_y, const CRadians& c_x) {
    const Real cz = std::cos(c_z.GetValue() / 2), sz = std::sin(c_z.GetValue() / 2);
    const Real cy = std::cos(c_y.GetValue() / 2), sy = std::sin(c_y.GetValue() / 2);
    const Real cx = std::cos(c_x.GetValue() / 2), sx = std::sin(c_x.GetValue() / 2);
    m_fW = cx * cy * cz + sx * sy * sz;
    m_fX = sx * cy * cz - cx * sy * sz;
    m_fY = cx * sy * cz + sx * cy * sz;
    m_fZ = cx * cy * sz - sx * sy * cz;
    return *this;
  }
  void ToEulerAngles(CRadians& c_z, CRadians& c_y, CRadians& c_x) const {
    c_z = CRadians(std::atan2(2 * (m_fW * m_fZ + m_fX * m_fY), 1 - 2 * (m_fY * m_fY + m_fZ * m_fZ)));
    const Real sine = 2 * (m_fW * m_fY - m_fZ * m_fX);
    c_y = CRadians(std::fabs(sine) >= 1 ? std::copysign(ARGOS_PI / 2, sine) : std::asin(sine));
    c_x = CRadians(std::atan2(2 * (m_fW * m_fX + m_fY * m_fZ), 1 - 2 * (m_fX * m_fX + m_fY * m_fY)));
  }
  void ToAngleAxis(CRadians& c_angle, CVector3& c_axis) const {
    c_angle = CRadians(2 * std::acos(m_fW));
    const Real s = std::sqrt(1 - m_fW * m_fW);
    c_axis = s < 1e-12 ? CVector3(1, 0, 0) : CVector3(m_fX / s, m_fY / s, m_fZ / s);
  }
  CQuaternion Inverse() const { return CQuaternion(m_fW, -m_fX, -m_fY, -m_fZ); }
  CQuaternion operator*(const CQuaternion& q) const {
    return CQuaternion(m_fW * q.m_fW - m_fX * q.m_fX - m_fY * q.m_fY - m_fZ * q.m_fZ,
                       m_fW * q.m_fX + m_fX * q.m_fW + m_fY * q.m_fZ - m_fZ * q.m_fY,
                       m_fW * q.m_fY - m_fX * q.m_fZ + m_fY * q.m_fW + m_fZ * q.m_fX,
                       m_fW * q.m_fZ + m_fX * q.m_fY - m_fY * q.m_fX + m_fZ * q.m_fW);
  }
  bool operator==(const CQuaternion& q) const {
    return m_fW == q.m_fW && m_fX == q.m_fX && m_fY == q.m_fY && m_fZ == q.m_fZ;
  }
  friend std::ostream& operator<<(std::ostream& os, const CQuaternion& q) {
    return os << q.m_fW << "," << q.m_fX << "," << q.m_fY << "," << q.m_fZ;
  }

 private:
  Real m_fW = 1, m_fX = 0, m_fY = 0, m_fZ = 0;
};

inline CVector3& CVector3::Rotate(const CQuaternion& q) {
  const CQuaternion rotated = q * CQuaternion(0, m_fX, m_fY, m_fZ) * q.Inverse();
  Set(rotated.GetX(), rotated.GetY(), rotated.GetZ());
  return *this;
}

}  // namespace argos
