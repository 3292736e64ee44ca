// The data blocks of the card deck (manual Sec. 22 DATA INPUT tables) and the card fields.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>
#include <vector>

#include "card_internal.hpp"
#include "card_model.hpp"
#include "field_description.hpp"

namespace tolip::ground::card_detail {
namespace {

constexpr unsigned bits(std::initializer_list<int> codes) {
  unsigned mask = 0;
  for (int code : codes) mask |= 1u << code;
  return mask;
}
constexpr unsigned kPowered = bits({1, 2, 3, 4, 5});
constexpr unsigned kAllStages = bits({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
constexpr unsigned kOpt = kOptimizationGroup;

std::vector<BlockSpec> make_blocks() {
  using F = Format;
  using S = Shape;
  return {
      {1, "MAIN HEADING", F::kText, 12, S::kWords, kOpt, 0, "", "", false},
      {2, "CASE HEADING", F::kText, 12, S::kWords, kOpt, 0, "", "", false},
      {3, "DATE", F::kText, 2, S::kWords, kOpt, 0, "", "", false},
      {4, "OPTIONS IP", F::kDigit, 24, S::kWords, kOpt, 0, "", "", false},
      {5, "STAGE SEQUENCE ISTGE", F::kInteger, 11, S::kWords, kOpt, 0, "", "", false},
      {6, "ADJUSTABLE PARAMETERS IB1", F::kInteger, 12, S::kWords, kOpt, 0, "", "", false},
      {8, "TRAJECTORY CONSTRAINT PARAMETERS IB3", F::kInteger, 14, S::kWords, kOpt, 0, "", "", false},
      {9, "OUTPUT FREQUENCY IB4", F::kInteger, 40, S::kWords, kOpt, 0, "", "", false},
      {10, "NOMINAL CONSTANTS CT1", F::kReal, 15, S::kWords, kOpt, 0, "", "", false},
      {11, "ATMOSPHERE CT2 BASE GEOPOTENTIAL ALTITUDE", F::kReal, 8, S::kWords, kOpt, 0, "", "", false},
      {12, "ATMOSPHERE CT3 BASE MOLECULAR TEMPERATURE", F::kReal, 8, S::kWords, kOpt, 0, "", "", false},
      {13, "ATMOSPHERE CT4 LAPSE RATE", F::kReal, 8, S::kWords, kOpt, 0, "", "", false},
      {14, "ATMOSPHERE CT5 BASE DENSITY", F::kReal, 8, S::kWords, kOpt, 0, "", "", false},
      {15, "EXTENSIONS: PAYLOAD, HEADING HOLD, LIFT STAGES", F::kReal, 4, S::kWords, kOpt, 0, "", "", true},
      {16, "STAGE DURATIONS AND INTEGRATION STEPS DA1", F::kReal, 20, S::kWords, kOpt, 0, "", "", false},
      {17, "INPUT DATA DA2", F::kReal, 20, S::kWords, kOpt, 0, "", "", false},
      {18, "PITCH PROGRAM LINEARIZATION TIMES TLIN", F::kReal, 17, S::kComplete, kOpt, 0, "", "", false},
      {19, "TRAJECTORY CONSTRAINT MAGNITUDES DA4", F::kReal, 13, S::kWords, kOpt, 0, "", "", false},
      {20, "INITIAL TIMES DA5", F::kReal, 2, S::kWords, kOpt, 0, "", "", false},
      {21, "INITIAL CONDITIONS DA6", F::kReal, 6, S::kWords, kOpt, 0, "", "", false},
      {22, "CONTROL VARIABLE CONSTRAINTS DA7", F::kReal, 6, S::kWords, kOpt, 0, "", "", false},
      {23, "IMPACT EXTENSIONS: REFERENCE AREAS, CASING WEIGHT", F::kReal, 3, S::kWords, kImpactGroup,
       bits({1, 2, 3}), "", "", true},
      {26, "LINEARIZATION SEGMENT WEIGHTS ETALIN", F::kReal, 15, S::kWords, kOpt, 0, "", "", false},
      {27, "OPTIMIZATION PARAMETER WEIGHTS DA12", F::kReal, 11, S::kWords, kOpt, 0, "", "", false},
      {28, "CONVERGENCE DATA DA13", F::kReal, 6, S::kWords, kOpt, 0, "", "", false},
      {29, "CONSTRAINT DEVIATIONS DA14", F::kReal, 26, S::kWords, kOpt, 0, "", "", false},
      {30, "VACUUM THRUST TABLE", F::kReal, 250, S::kPairs, kOpt | kDispersionGroup, kPowered,
       "STAGE TIME, S", "VACUUM THRUST, LB", false},
      {31, "DRAG COEFFICIENT TABLE (ALPHA = 0)", F::kReal, kTableWords, S::kTable, kOpt, kAllStages, "MACH",
       "CD", false},
      {32, "LIFT COEFFICIENT PER ALPHA TABLE TL1", F::kReal, kTableWords, S::kTable, kOpt, 0, "MACH",
       "CL ALPHA, PER RAD", false},
      {33, "DATA FOR 6D SIMULATION DA6D", F::kReal, 30, S::kWords, kOpt | kHardoverGroup | kImpactGroup, 0,
       "", "", false},
      {34, "FIN NORMAL FORCE COEFFICIENT PER DELTA", F::kReal, kTableWords, S::kTable, kOpt, 0, "MACH",
       "CN DELTA, PER RAD PER FIN", false},
      {35, "PITCHING MOMENT COEFFICIENT PER ALPHA", F::kReal, kTableWords, S::kTable, kOpt | kDispersionGroup,
       0, "MACH", "CM ALPHA, PER RAD", false},
      {36, "FIN PITCHING MOMENT COEFFICIENT PER DELTA", F::kReal, kTableWords, S::kTable, kOpt, 0, "MACH",
       "CM DELTA, PER RAD PER FIN", false},
      {37, "STAGE CENTER OF GRAVITY HISTORY", F::kReal, kTableWords, S::kTable, kOpt | kHardoverGroup,
       bits({1, 2, 3, 4}), "STAGE TIME, S", "C.G. STATION, IN", false},
      {38, "CONSUMABLE WEIGHT REMAINING TABLE", F::kReal, 250, S::kPairs, kOpt | kDispersionGroup, kPowered,
       "STAGE TIME, S", "WEIGHT REMAINING, LB", false},
      {39, "STAGE DATA SG", F::kReal, 3, S::kWords, kOpt, kAllStages, "", "", false},
      {40, "THETA HISTORY FOR NOMINAL TRAJECTORY TTH", F::kReal, 32, S::kTable, kOpt, 0,
       "TIME FROM LAUNCH, S", "THETA, DEG", false},
      {41, "RADAR STATION LOCATIONS", F::kStation, 5, S::kWords, kRadarGroup, 0, "", "", false},
      {42, "IMPACT FAILURE MODE DRAG TABLE", F::kReal, kTableWords, S::kTable, kImpactGroup, bits({1, 2, 3}),
       "MACH", "CD", false},
      {43, "IMPACT EXPENDED CASING DRAG TABLE", F::kReal, kTableWords, S::kTable, kImpactGroup,
       bits({1, 2, 3}), "MACH", "CD", false},
      {44, "HARDOVER IYY (STAGES 1-3) OR CMQ (CODE 4) TABLE", F::kReal, kTableWords, S::kTable,
       kHardoverGroup, bits({1, 2, 3, 4}), "STAGE TIME, S / MACH", "IYY, SLUG FT2 / CMQ, PER RAD", false},
      {45, "HARDOVER DATA", F::kReal, 26, S::kWords, kHardoverGroup, 0, "", "", false},
      {46, "DISPERSION TRAJECTORY CODE AND TITLE", F::kText, 2, S::kWords, kDispersionGroup, 0, "", "",
       false},
      {47, "STAGE WEIGHT INCREMENT", F::kReal, 1, S::kWords, kDispersionGroup, bits({1, 2, 3, 4, 5}), "", "",
       false},
      {48, "PERCENTAGE DRAG VARIATION", F::kReal, 1, S::kWords, kDispersionGroup, 0, "", "", false},
      {49, "STAGE 1 THRUST MISALIGNMENT", F::kReal, 2, S::kWords, kDispersionGroup, bits({1}), "", "", false},
      {50, "CONTROL SYSTEM DEADBAND ANGLE", F::kReal, 1, S::kWords, kDispersionGroup, bits({2, 3}), "", "",
       false},
      {51, "FOURTH OR FIFTH STAGE TIPOFF", F::kReal, 1, S::kWords, kDispersionGroup, bits({4, 5}), "", "",
       false},
      {52, "LAUNCH DISPERSIONS", F::kReal, 1, S::kWords, kDispersionGroup, 0, "", "", false},
      {53, "WIND VELOCITY WINDVL", F::kReal, kTableWords, S::kTable, kDispersionGroup, 0, "ALTITUDE, FT",
       "WIND SPEED, FT/S", false},
      {54, "WIND AZIMUTH WINDAZ", F::kReal, kTableWords, S::kTable, kDispersionGroup, 0, "ALTITUDE, FT",
       "WIND AZIMUTH, DEG FROM NORTH", false},
      {55, "STAGE 4 AND 5 DURATIONS", F::kReal, 2, S::kWords, kDispersionGroup, 0, "", "", false},
  };
}

std::string numbered(const char* text, int n) { return std::string(text) + " " + std::to_string(n); }

}  // namespace

const std::vector<BlockSpec>& all_blocks() {
  static const std::vector<BlockSpec> blocks = make_blocks();
  return blocks;
}

const BlockSpec* find_block(int number) {
  for (const BlockSpec& spec : all_blocks()) {
    if (spec.number == number) return &spec;
  }
  return nullptr;
}

int block_size(const BlockSpec& spec, int stage) {
  if (spec.number == 39 && stage >= 6) return 2;
  return spec.size;
}

int fields_per_card(Format format) {
  switch (format) {
    case Format::kText: return 12;     // 12A6, columns 1-72
    case Format::kDigit: return 24;    // 24I1, columns 1-24
    case Format::kInteger: return 24;  // I3, columns 1-72
    case Format::kReal: return 6;      // E12.8, columns 1-72
    case Format::kStation: return 1;   // one station per card
  }
  return 1;
}

int field_width(Format format) {
  switch (format) {
    case Format::kText: return 6;
    case Format::kDigit: return 1;
    case Format::kInteger: return 3;
    case Format::kReal: return 12;
    case Format::kStation: return 80;
  }
  return 1;
}

std::string stage_list(unsigned stages) {
  std::string out;
  int run_start = 0;
  for (int code = 1; code <= 11; ++code) {
    const bool on = code <= 10 && (stages & (1u << code)) != 0;
    if (on && run_start == 0) run_start = code;
    if (!on && run_start != 0) {
      const int run_end = code - 1;
      if (!out.empty()) out += ", ";
      out += std::to_string(run_start);
      if (run_end > run_start + 1) {
        out += '-';
        out += std::to_string(run_end);
      }
      if (run_end == run_start + 1) {
        out += ", ";
        out += std::to_string(run_end);
      }
      run_start = 0;
    }
  }
  return out;
}

std::string group_name(unsigned group) {
  switch (group) {
    case kOptimizationGroup: return "the optimization data (data blocks 1-40, before the first blank card)";
    case kDispersionGroup: return "the dispersion data (IP(21))";
    case kHardoverGroup: return "the hardover data (IP(22))";
    case kImpactGroup: return "the impact data (IP(23))";
    case kRadarGroup: return "the radar data (IP(24))";
    default: break;
  }
  std::string out;
  for (unsigned bit : {kOptimizationGroup, kDispersionGroup, kHardoverGroup, kImpactGroup, kRadarGroup}) {
    if ((group & bit) == 0) continue;
    if (!out.empty()) out += " or ";
    out += group_name(bit);
  }
  return out;
}

std::string word_description(int block, int stage, int word) {
  const BlockSpec* spec = find_block(block);
  if (spec == nullptr || word < 1 || word > block_size(*spec, stage)) return "";
  if (spec->shape == Shape::kTable) {
    if (word == 1) return "BLANK";
    return word % 2 == 0 ? std::string(spec->x_name) + " (OR 1.0E10 END)" : spec->y_name;
  }
  if (spec->shape == Shape::kPairs) return word % 2 == 1 ? spec->x_name : spec->y_name;
  int index = 0;
  int code = 0;
  if (const deck_detail::FieldDescription* field =
          deck_detail::find_field(block, stage, word, &index, &code)) {
    return deck_detail::card_text_of(*field, code, index);
  }
  switch (block) {
    case 1:
    case 2:
    case 3:
    case 46: return "CHARACTERS " + std::to_string(6 * word - 5) + "-" + std::to_string(6 * word);
    case 5: return numbered("STAGE CODE (0 ENDS), FLIGHT POSITION", word);
    case 6:
      return word == 1 ? "NUMBER OF ADJUSTABLE PARAMETERS" : numbered("ADJUSTABLE PARAMETER CODE", word - 1);
    case 8:
      if (word == 1) return "NUMBER OF CONSTRAINTS WITH PAYOFF";
      return word == 2 ? "PAYOFF CODE" : numbered("CONSTRAINT CODE", word - 1);
    case 9: {
      const int group = (word - 1) / 4 + 1;
      static const char* const kKinds[] = {"INITIAL: EVERY N-TH POINT", "INTERMED.: EVERY N-TH POINT",
                                           "FINAL: EVERY N-TH POINT", "STAGE CODE"};
      return std::string(kKinds[(word - 1) % 4]) + ", GROUP " + std::to_string(group);
    }
    case 15:
      return word == 1 ? "PAYLOAD, LB (EXTENSION)" : word == 3 ? "LIFT TABLE STAGES 0/1/6/16 (EXT.)" : "";
    case 18:
      return word == 1 ? "NUMBER OF LINEAR SEGMENTS" : numbered("CODED TIME 100N+T, BOUNDARY", word - 1);
    case 19: return numbered("DESIRED VALUE (FT,RAD,NMI), CONSTR.", word);
    case 23: {
      static const char* const kWords[] = {"FAILURE DRAG REF. AREA, FT2 (EXT.)",
                                           "CASING DRAG REF. AREA, FT2 (EXT.)",
                                           "CASING WEIGHT, LB (EXTENSION)"};
      return kWords[word - 1];
    }
    case 26: return numbered("WEIGHT OF LINEAR SEGMENT", word);
    case 27: return numbered("WEIGHT OF ADJUSTABLE PARAMETER CODE", word);
    case 29:
      if (word == 13 || word == 26) return "";
      return word < 13 ? numbered("OPTIMIZATION DEADBAND, CONSTRAINT", word + 1)
                       : numbered("LINEARIZATION DEADBAND, CONSTRAINT", word - 12);
    case 41: {
      static const char* const kWords[] = {"STATION IDENTIFICATION", "GEODETIC LATITUDE, DEG",
                                           "LONGITUDE, DEG EAST", "ALTITUDE, FT", "DESCRIPTION (EXTENSION)"};
      return kWords[word - 1];
    }
    case 47: return "JETTISON WEIGHT INCREMENT, LB";
    case 48: return "DRAG VARIATION FRACTION 0.XXXX";
    case 49: return word == 1 ? "MISALIGNMENT ANGLE, DEG" : "THRUST APPLICATION STATION, IN";
    case 50: return "DEADBAND ANGLE, DEG";
    case 51: return "TIP-OFF ATTITUDE CHANGE, DEG";
    case 52: return "AZIMUTH OR ATTITUDE CHANGE, DEG";
    case 55: return word == 1 ? "STAGE 4 DURATION, S" : "STAGE 5 DURATION, S";
    default: break;
  }
  return "";
}

// ---- fields -------------------------------------------------------------------------------------

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

std::string quote(const std::string& text) { return "'" + text + "'"; }

std::string bad_character(char c, const std::string& field, const char* kind) {
  if (is_letter(c)) {
    return std::string("letter '") + c + "' in a numeric field: " + quote(field) + " is not " + kind;
  }
  return std::string("unexpected character '") + c + "' in " + quote(field) + ": expected " + kind;
}

}  // namespace

bool parse_real_field(const std::string& field, double* value, std::string* problem) {
  std::size_t begin = 0;
  std::size_t end = field.size();
  while (begin < end && field[begin] == ' ') ++begin;
  while (end > begin && field[end - 1] == ' ') --end;
  *value = 0.0;
  if (begin == end) return true;
  const std::string text = field.substr(begin, end - begin);
  const char* kKind = "an E12.8 number such as 1.5, -.25 or 1.0E10";
  std::string normalized;
  std::size_t i = 0;
  if (text[i] == '+' || text[i] == '-') {
    if (text[i] == '-') normalized += '-';
    ++i;
  }
  bool point = false;
  bool nonzero = false;
  int digits = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (is_digit(c)) {
      ++digits;
      nonzero = nonzero || c != '0';
      normalized += c;
    } else if (c == '.' && !point) {
      point = true;
      normalized += c;
    } else {
      break;
    }
  }
  if (digits == 0) {
    if (i < text.size() && text[i] == ' ') *problem = "blank inside the number " + quote(text);
    else if (i < text.size()) *problem = bad_character(text[i], text, kKind);
    else *problem = quote(text) + " has no digits: expected " + std::string(kKind);
    return false;
  }
  if (i < text.size()) {
    const char c = text[i];
    const bool letter = c == 'E' || c == 'e' || c == 'D' || c == 'd';
    if (letter || c == '+' || c == '-') {
      if (letter) ++i;
      normalized += 'e';
      if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
        if (text[i] == '-') normalized += '-';
        ++i;
      }
      int exponent_digits = 0;
      for (; i < text.size() && is_digit(text[i]); ++i) {
        ++exponent_digits;
        normalized += text[i];
      }
      if (exponent_digits == 0) {
        *problem = "exponent without digits in " + quote(text) + ": expected " + kKind;
        return false;
      }
    }
  }
  if (i < text.size()) {
    if (text[i] == ' ')
      *problem = "blank inside the number " + quote(text) + " (FORTRAN would read it as a 0)";
    else *problem = bad_character(text[i], text, kKind);
    return false;
  }
  if (!point && nonzero) {
    const std::size_t mantissa_end = text.find_first_of("EeDd+-", 1);
    const std::string mantissa =
        text.substr(0, mantissa_end == std::string::npos ? text.size() : mantissa_end);
    *problem = quote(text) +
               " has no decimal point: in an E12.8 field FORTRAN scales such a number by 1.0E-8; write " +
               quote(mantissa + "." + (mantissa_end == std::string::npos ? "" : text.substr(mantissa_end))) +
               " for the whole number";
    return false;
  }
  double parsed = 0.0;
  const char* first = normalized.data();
  const char* last = normalized.data() + normalized.size();
  const std::from_chars_result result = std::from_chars(first, last, parsed, std::chars_format::general);
  if (result.ec == std::errc::result_out_of_range) {
    *problem = quote(text) + " is out of the range of a double";
    return false;
  }
  if (result.ec != std::errc() || result.ptr != last || !std::isfinite(parsed)) {
    *problem = quote(text) + " is not a number: expected " + std::string(kKind);
    return false;
  }
  *value = parsed;
  return true;
}

bool parse_integer_field(const std::string& field, int* value, std::string* problem) {
  *value = 0;
  std::size_t begin = 0;
  while (begin < field.size() && field[begin] == ' ') ++begin;
  if (begin == field.size()) return true;
  std::size_t end = field.size();
  while (end > begin && field[end - 1] == ' ') --end;
  const std::string text = field.substr(begin, end - begin);
  const char* kKind = "an integer right-justified in its field";
  std::size_t i = 0;
  bool negative = false;
  if (text[0] == '+' || text[0] == '-') {
    negative = text[0] == '-';
    ++i;
  }
  if (i == text.size()) {
    *problem = "sign without digits in " + quote(field) + ": expected " + kKind;
    return false;
  }
  int result = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ') {
      *problem =
          "blank inside the integer " + quote(field) + " (FORTRAN would read it as a 0): expected " + kKind;
      return false;
    }
    if (!is_digit(c)) {
      *problem = c == '.' ? "decimal point in the integer field " + quote(field) + ": expected " + kKind
                          : bad_character(c, field, kKind);
      return false;
    }
    result = result * 10 + (c - '0');
  }
  if (end < field.size()) {
    *problem = "integer " + quote(field) +
               " is not right-justified: FORTRAN reads the trailing blanks as zeros (" +
               quote(text + std::string(field.size() - end, '0')) +
               "); expected the number to end in the field's last column";
    return false;
  }
  *value = negative ? -result : result;
  return true;
}

namespace {

// The shortest rendering of `value` rounded to `precision` significant digits, with a decimal
// point: fixed ("-.0025", "125.") or exponent ("1.5E10") form, whichever is shorter.
std::string render(double value, int precision) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*e", precision - 1, value);
  std::string text(buffer);
  const bool negative = text[0] == '-';
  if (negative) text.erase(0, 1);
  const std::size_t e = text.find('e');
  const int exponent = std::stoi(text.substr(e + 1));
  std::string digits;
  for (std::size_t i = 0; i < e; ++i) {
    if (is_digit(text[i])) digits += text[i];
  }
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
  if (digits == "0") return "0.";
  const std::string sign = negative ? "-" : "";
  // Exponent form: d.ddddE[-]x
  std::string exp_form = sign + digits.substr(0, 1) + "." + digits.substr(1) + "E" + std::to_string(exponent);
  // Fixed form.
  std::string fixed;
  const int count = static_cast<int>(digits.size());
  if (exponent >= 0) {
    if (exponent + 1 >= count) {
      fixed = digits + std::string(static_cast<std::size_t>(exponent + 1 - count), '0') + ".";
    } else {
      fixed = digits.substr(0, static_cast<std::size_t>(exponent + 1)) + "." +
              digits.substr(static_cast<std::size_t>(exponent + 1));
    }
  } else {
    fixed = ".";
    fixed.append(static_cast<std::size_t>(-exponent - 1), '0');
    fixed += digits;
  }
  fixed = sign + fixed;
  // Fixed notation reads best; the exponent form only when the fixed one would not fit.
  return fixed.size() <= 12 || fixed.size() <= exp_form.size() ? fixed : exp_form;
}

}  // namespace

std::string format_real_field(double value, int width, bool* exact) {
  if (!std::isfinite(value)) {
    if (exact != nullptr) *exact = false;
    return "0.";
  }
  if (value == 0.0) {
    if (exact != nullptr) *exact = true;
    return "0.";
  }
  if (value == kTableEnd) {
    if (exact != nullptr) *exact = true;
    return "1.0E10";
  }
  std::string best;
  for (int precision = 1; precision <= 17; ++precision) {
    const std::string text = render(value, precision);
    if (static_cast<int>(text.size()) > width) continue;
    best = text;
    double back = 0.0;
    std::string problem;
    if (parse_real_field(text, &back, &problem) && back == value) {
      if (exact != nullptr) *exact = true;
      return text;
    }
  }
  if (exact != nullptr) *exact = false;
  return best.empty() ? render(value, 1) : best;
}

}  // namespace tolip::ground::card_detail
