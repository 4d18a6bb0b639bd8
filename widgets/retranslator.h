#pragma once
// Rewords the texts already on screen when the operator switches language at run
// time. Widgets that build their words in a retranslateUi() (the window, the
// connection bar, the event log, the API panel) do that themselves on LanguageChange;
// every other text a screen shows was set once with tr() and would stay in the old
// language until the screen next changes it. The retranslator finds each such text in
// the translation catalogue (the zh_CN .ts, embedded), in the language it is shown in,
// and sets the same entry in the new one: labels, buttons, group and tab titles,
// tooltips, placeholders, combo and list items, table headers, menus and actions,
// spin-box affixes, plot axes, legends and titles. A sentence with arguments
// ("已选 %1 个孔：%2") is matched as a pattern and its arguments carried over.
// Where one English text has several translations, the context of the nearest
// enclosing class that has the text decides.
//
// A text that is not in the catalogue (data: a file name, a well, a device's model)
// is left as it is.
#include <QList>
#include <QString>
#include <QStringList>

class QWidget;

namespace ui {

class Retranslator {
public:
    /// Rewords every text of `roots` and their children from `from` to `to` ("en" or
    /// "zh_CN"); returns how many texts changed.
    static int retranslate(const QList<QWidget*>& roots, const QString& from, const QString& to);
    /// One text from `from` to `to`; `contexts` are the class names to prefer, nearest
    /// first. The text itself when the catalogue does not have it.
    static QString reword(const QString& text, const QStringList& contexts, const QString& from, const QString& to);
    /// A combo's bool property: its items are names (data), never reworded.
    static constexpr const char* kItemsAreNames = "bpItemsAreNames";
};

} // namespace ui
