// geometry/pattern/internal/try.h: early-return helpers for Result/Status in importer code.
#pragma once

/// Evaluates `expr` (a Result<T>); on failure returns its error, else binds the value to `var`.
#define TP_TRY(var, expr)                                \
  auto var##_r = (expr);                                 \
  if (!var##_r) return std::unexpected(var##_r.error()); \
  auto var = std::move(*var##_r)

/// Evaluates `expr` (a Status or Result); on failure returns its error.
#define TP_CHECK(expr)                                              \
  do {                                                              \
    auto tp_check_r = (expr);                                       \
    if (!tp_check_r) return std::unexpected(tp_check_r.error());    \
  } while (0)
