// tests/fuzz/compat/expected_polyfill.h: std::expected for the clang 14 fuzz build only.
//
// Debian 12's clang 14 cannot compile libstdc++ 12's <expected> (it lacks C++20 conditionally
// trivial special members), so the fuzz build puts this folder on its include path and the
// layers' error headers include it when __cpp_lib_expected is missing. It implements the
// subset of std::expected the project uses; g++ builds never see it.
#pragma once

#include <type_traits>
#include <utility>
#include <variant>

namespace std {

template <class E>
class unexpected {
 public:
  template <class G = E>
  constexpr explicit unexpected(G&& e) : e_(std::forward<G>(e)) {}
  constexpr const E& error() const& { return e_; }
  constexpr E& error() & { return e_; }
  constexpr E&& error() && { return std::move(e_); }

 private:
  E e_;
};
template <class E>
unexpected(E) -> unexpected<E>;

template <class T, class E>
class expected {
 public:
  using value_type = T;
  using error_type = E;
  constexpr expected() : v_(std::in_place_index<0>) {}
  template <class U = T, class = std::enable_if_t<std::is_constructible_v<T, U&&> &&
                                                  !std::is_same_v<std::decay_t<U>, expected>>>
  constexpr expected(U&& v) : v_(std::in_place_index<0>, std::forward<U>(v)) {}
  template <class G>
  constexpr expected(const unexpected<G>& u) : v_(std::in_place_index<1>, u.error()) {}
  template <class G>
  constexpr expected(unexpected<G>&& u) : v_(std::in_place_index<1>, std::move(u).error()) {}

  constexpr bool has_value() const { return v_.index() == 0; }
  constexpr explicit operator bool() const { return has_value(); }
  constexpr T& value() & { return std::get<0>(v_); }
  constexpr const T& value() const& { return std::get<0>(v_); }
  constexpr T&& value() && { return std::get<0>(std::move(v_)); }
  constexpr T& operator*() & { return std::get<0>(v_); }
  constexpr const T& operator*() const& { return std::get<0>(v_); }
  constexpr T&& operator*() && { return std::get<0>(std::move(v_)); }
  constexpr T* operator->() { return &std::get<0>(v_); }
  constexpr const T* operator->() const { return &std::get<0>(v_); }
  constexpr E& error() & { return std::get<1>(v_); }
  constexpr const E& error() const& { return std::get<1>(v_); }
  constexpr E&& error() && { return std::get<1>(std::move(v_)); }
  template <class U>
  constexpr T value_or(U&& d) const& { return has_value() ? value() : static_cast<T>(std::forward<U>(d)); }

 private:
  std::variant<T, E> v_;
};

template <class E>
class expected<void, E> {
 public:
  using value_type = void;
  using error_type = E;
  constexpr expected() = default;
  template <class G>
  constexpr expected(const unexpected<G>& u) : ok_(false), e_(u.error()) {}
  template <class G>
  constexpr expected(unexpected<G>&& u) : ok_(false), e_(std::move(u).error()) {}
  constexpr bool has_value() const { return ok_; }
  constexpr explicit operator bool() const { return ok_; }
  constexpr void value() const {}
  constexpr void operator*() const {}
  constexpr const E& error() const& { return e_; }
  constexpr E& error() & { return e_; }

 private:
  bool ok_ = true;
  E e_{};
};

}  // namespace std
