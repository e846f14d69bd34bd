#pragma once

#include <QString>
#include <QStringList>

namespace opentop {

// The fonts a language is read in. Chinese, Japanese and Korean share Han characters whose
// shapes differ by language (門, 骨, 直); a font is made for one. Left to itself the system
// picks by its own locale, not by OpenTOP's language: on an English Debian, Traditional Chinese
// was drawn with Noto Sans CJK JP's Japanese shapes. So the application font names the
// language's own CJK family first, then the others (a Korean drive name in a Chinese window
// still has a font: never boxes), on Linux the Noto CJK families, on Windows the system's
// (Microsoft JhengHei, YaHei, Malgun Gothic, Yu Gothic).
class LanguageFont
{
public:
    // The CJK families for `language` ("zh_TW", "ja", "en"...), its own first.
    static QStringList familiesFor(const QString& language, bool windows);
    // Puts them behind the application font's own family (Latin text keeps its font).
    static void apply(const QString& language);
};

} // namespace opentop
