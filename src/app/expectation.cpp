#include "app/expectation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/file_column.h"
#include "core/strings.h"

namespace essaim {

namespace {
const std::vector<std::string> kOps = {"==", "!=", "<=", ">=", "<", ">"};
const std::vector<std::string> kAggregates = {"each", "mean", "median", "min", "max", "quantile", "fraction"};

/// A ratio written with spaces around its '/' splits VALUE in three: say how it is written.
std::string RatioHint(const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos || (text.find(" /") == std::string::npos && text.find("/ ") == std::string::npos))
    return "";
  std::string joined = text;
  while (joined.find(" /") != std::string::npos) joined.erase(joined.find(" /"), 1);
  while (joined.find("/ ") != std::string::npos) joined.erase(joined.find("/ ") + 1, 1);
  return "; a ratio is written without spaces around '/': '" + Trim(joined) + "'";
}

/// "VALUE OP N" (the whole of `text`) into value and comparison.
bool ParseCondition(const std::string& text, std::string* value, Comparison* c, std::string* error) {
  std::istringstream in(text);
  std::string number, rest;
  if (!(in >> *value >> c->op >> number) || (in >> rest)) {
    *error = "'" + Trim(text) + "' is not 'VALUE OP NUMBER' (e.g. 'errors == 0')" + RatioHint(text);
    return false;
  }
  if (std::find(kOps.begin(), kOps.end(), c->op) == kOps.end()) {
    *error = "unknown comparison '" + c->op + "' (==, !=, <, <=, >, >=)";
    return false;
  }
  std::optional<double> n = number == "true" ? 1.0 : number == "false" ? 0.0 : ParseDouble(number);
  if (!n) *error = "'" + number + "' is not a number";
  c->threshold = n.value_or(0);
  return n.has_value();
}

/// The aggregate word and what follows it; `inner` is the text in parentheses, if any.
bool SplitHead(const std::string& text, std::string* head, std::string* inner, std::string* rest, std::string* error) {
  size_t open = text.find('(');
  size_t space = text.find(' ');
  if (open != std::string::npos && open < space) {
    size_t close = text.rfind(')');
    if (close == std::string::npos || close < open) {
      *error = "'(' without ')'";
      return false;
    }
    *head = Trim(text.substr(0, open));
    *inner = text.substr(open + 1, close - open - 1);
    *rest = text.substr(close + 1);
    return true;
  }
  *head = text.substr(0, space);
  *rest = space == std::string::npos ? "" : text.substr(space + 1);
  return true;
}

/// Each file column of VALUE (A/B included) well formed.
bool CheckFileValues(const std::string& value, std::string* error) {
  const size_t slash = RatioSlash(value);
  if (slash != std::string::npos)
    return CheckFileValues(value.substr(0, slash), error) && CheckFileValues(value.substr(slash + 1), error);
  return !IsFileValue(value) || CheckFileValue(value, error);
}

bool ParseAggregate(const std::string& head, Aggregate* out, std::string* error) {
  auto it = std::find(kAggregates.begin(), kAggregates.end(), head);
  if (it == kAggregates.end()) {
    std::string hint = ClosestName(head, kAggregates);
    *error = "'" + head + "' is not each, mean, median, min, max, quantile(P) or fraction(...)" +
             (hint.empty() ? "" : "; did you mean '" + hint + "'?");
    return false;
  }
  *out = static_cast<Aggregate>(it - kAggregates.begin());
  return true;
}
}  // namespace

bool Comparison::Holds(double v) const {
  if (op == "==") return v == threshold;
  if (op == "!=") return v != threshold;
  if (op == "<") return v < threshold;
  if (op == "<=") return v <= threshold;
  if (op == ">") return v > threshold;
  return v >= threshold;
}

bool ParseExpectation(const std::string& text, Expectation* out, std::string* error) {
  out->text = Trim(text);
  std::string head, inner, rest;
  if (!SplitHead(out->text, &head, &inner, &rest, error) || !ParseAggregate(head, &out->aggregate, error)) return false;
  bool wants_inner = out->aggregate == Aggregate::Quantile || out->aggregate == Aggregate::Fraction;
  if (wants_inner != !inner.empty() || (wants_inner && inner.empty())) {
    *error = wants_inner ? head + " needs its argument in parentheses: " +
                               (head == "quantile" ? "quantile(0.1) VALUE OP N" : "fraction(VALUE OP N) OP F")
                         : head + " takes no argument in parentheses";
    return false;
  }
  if (out->aggregate == Aggregate::Fraction) {
    std::string dummy;
    if (!ParseCondition(inner, &out->value, &out->per_run, error) || !CheckFileValues(out->value, error)) return false;
    return ParseCondition("fraction " + rest, &dummy, &out->check, error);
  }
  if (out->aggregate == Aggregate::Quantile) {
    std::optional<double> q = ParseDouble(Trim(inner));
    if (!q || *q < 0 || *q > 1) {
      *error = "quantile(" + inner + "): P is a number from 0 to 1";
      return false;
    }
    out->quantile = *q;
  }
  return ParseCondition(rest, &out->value, &out->check, error) && CheckFileValues(out->value, error);
}

}  // namespace essaim
