// ARGoS's CAny (argos3/core/utility/datatypes/any.h): a value of any copyable type, read
// back with any_cast<T> (CSpace::TMapPerType holds entity pointers in them).
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>

#include <memory>
#include <typeinfo>

namespace argos {

class CAny {
 public:
  CAny() = default;
  template <typename T>
  CAny(const T& value) : m_held(new CHolder<T>(value)) {}  // NOLINT: implicit, as ARGoS
  CAny(const CAny& other) : m_held(other.m_held ? other.m_held->Clone() : nullptr) {}
  CAny& operator=(const CAny& other) {
    m_held.reset(other.m_held ? other.m_held->Clone() : nullptr);
    return *this;
  }
  bool Empty() const { return !m_held; }
  const std::type_info& GetType() const { return m_held ? m_held->Type() : typeid(void); }

  /// The held value when it is a T, else null.
  template <typename T>
  T* Get() {
    if (!m_held || m_held->Type() != typeid(T)) return nullptr;
    return &static_cast<CHolder<T>*>(m_held.get())->Value;
  }

 private:
  struct CPlaceHolder {
    virtual ~CPlaceHolder() = default;
    virtual const std::type_info& Type() const = 0;
    virtual CPlaceHolder* Clone() const = 0;
  };
  template <typename T>
  struct CHolder : CPlaceHolder {
    explicit CHolder(const T& value) : Value(value) {}
    const std::type_info& Type() const override { return typeid(T); }
    CPlaceHolder* Clone() const override { return new CHolder(Value); }
    T Value;
  };
  std::unique_ptr<CPlaceHolder> m_held;
};

template <typename T>
T* any_cast(CAny* pc_any) {
  return pc_any ? pc_any->Get<T>() : nullptr;
}

template <typename T>
T& any_cast(CAny& c_any) {
  T* value = c_any.Get<T>();
  if (!value) THROW_ARGOSEXCEPTION("any_cast: the value is not a " << typeid(T).name());
  return *value;
}

}  // namespace argos
