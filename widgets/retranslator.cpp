#include "retranslator.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QGroupBox>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QProgressBar>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>
#include <QXmlStreamReader>

#include <qcustomplot.h>

#include <memory>
#include <vector>

namespace ui {
namespace {

/// One catalogue entry: the English source and its Chinese.
struct CatalogueEntry {
    QString context;
    QString en;
    QString zh;
};

/// A sentence with arguments in one language, as a regular expression.
struct SentencePattern {
    int entry = 0;
    QRegularExpression re;
    QString chunk;             ///< its longest literal part: a cheap test before the expression
    QVector<QString> holders;  ///< the placeholder of each capture, in order ("%1", "%L2")
};

class Catalogue {
public:
    static const Catalogue& instance()
    {
        static const Catalogue c;
        return c;
    }
    const std::vector<CatalogueEntry>& entries() const { return m_entries; }
    const QVector<int>& exact(bool zh, const QString& text) const
    {
        static const QVector<int> none;
        const auto& map = zh ? m_byZh : m_byEn;
        const auto it = map.find(text);
        return it == map.end() ? none : *it;
    }
    const std::vector<SentencePattern>& patterns(bool zh) const { return zh ? m_zhPatterns : m_enPatterns; }

private:
    Catalogue()
    {
        QFile f(QStringLiteral(":/i18n-source/benchpilot_zh_CN.ts"));
        if (!f.open(QIODevice::ReadOnly))
            return;
        QXmlStreamReader xml(&f);
        QString context;
        CatalogueEntry e;
        bool numerus = false, finished = true;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) {
                if (xml.isEndElement() && xml.name() == QLatin1String("message") && !numerus && finished && !e.zh.isEmpty()
                    && e.zh != e.en)
                    add(e);
                continue;
            }
            const auto name = xml.name();
            if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                e = CatalogueEntry{context, {}, {}};
                numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            } else if (name == QLatin1String("source")) {
                e.en = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            } else if (name == QLatin1String("translation")) {
                finished = xml.attributes().value(QLatin1String("type")) != QLatin1String("unfinished");
                if (!numerus)
                    e.zh = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            }
        }
    }

    void add(const CatalogueEntry& e)
    {
        const int index = static_cast<int>(m_entries.size());
        m_entries.push_back(e);
        m_byEn[e.en].push_back(index);
        m_byZh[e.zh].push_back(index);
        static const QRegularExpression holder(QStringLiteral("%L?[1-9]"));
        if (!e.en.contains(holder))
            return;
        // A template with no words of its own ("%1", "%1：%2") would match almost any
        // text in that language: such texts are reworded piece by piece instead.
        static const QRegularExpression holders(QStringLiteral("%L?[1-9]"));
        static const QRegularExpression word(QStringLiteral("\\p{L}"));
        if (QString(e.en).remove(holders).contains(word))
            m_enPatterns.push_back(pattern(index, e.en));
        if (QString(e.zh).remove(holders).contains(word))
            m_zhPatterns.push_back(pattern(index, e.zh));
    }

    static SentencePattern pattern(int index, const QString& text)
    {
        static const QRegularExpression holder(QStringLiteral("%L?[1-9]"));
        SentencePattern p;
        p.entry = index;
        QString re = QStringLiteral("^");
        int at = 0;
        auto literal = [&](const QString& part) {
            re += QRegularExpression::escape(part);
            if (part.size() > p.chunk.size())
                p.chunk = part;
        };
        for (auto it = holder.globalMatch(text); it.hasNext();) {
            const auto m = it.next();
            literal(text.mid(at, m.capturedStart() - at));
            re += QStringLiteral("(.*?)");
            p.holders.push_back(m.captured());
            at = m.capturedEnd();
        }
        literal(text.mid(at));
        re += QStringLiteral("$");
        p.re = QRegularExpression(re, QRegularExpression::DotMatchesEverythingOption);
        return p;
    }

    std::vector<CatalogueEntry> m_entries;
    QHash<QString, QVector<int>> m_byEn, m_byZh;
    std::vector<SentencePattern> m_enPatterns, m_zhPatterns;
};

bool isChinese(const QString& language) { return language.startsWith(QLatin1String("zh")); }

/// Of the entries that have the text, the one whose context is nearest in `contexts`.
int pick(const QVector<int>& candidates, const QStringList& contexts)
{
    const auto& entries = Catalogue::instance().entries();
    for (const QString& c : contexts)
        for (int i : candidates)
            if (entries[static_cast<std::size_t>(i)].context == c)
                return i;
    return candidates.front();
}

QString inLanguage(const CatalogueEntry& e, bool zh) { return zh ? e.zh : e.en; }

/// The class names around `w`, nearest first, each with its base classes.
QStringList contextsOf(const QObject* w)
{
    QStringList out;
    for (const QObject* o = w; o; o = o->parent())
        for (const QMetaObject* m = o->metaObject(); m; m = m->superClass())
            out << QString::fromLatin1(m->className());
    return out;
}

/// True when `text` is a catalogue entry, but only of contexts other than the widget's:
/// in a combo or a list that is most likely a name from a file ("wash" the station,
/// not "wash" the step), and names are never reworded.
bool foreignWord(const QString& text, const QStringList& contexts, bool fromZh)
{
    const Catalogue& cat = Catalogue::instance();
    const QVector<int>& exact = cat.exact(fromZh, text);
    if (exact.isEmpty())
        return false;
    for (int i : exact)
        if (contexts.contains(cat.entries()[static_cast<std::size_t>(i)].context))
            return false;
    return true;
}

/// Where a widget keeps what the retranslator made of its texts (a QVariantMap, so it is
/// never taken for a text to reword itself): for each of its texts, the text it showed in
/// the language switched from and the one set in the language switched to. Switching back
/// gives the text it had, not the catalogue's best guess: an English word can be one of
/// several that share a Chinese one ("Home" and "home", "Go" and "move").
constexpr const char* kWordedProperty = "_bp_worded";

struct Rewording {
    bool fromZh = false, toZh = false;
    int changed = 0;
    QObject* owner = nullptr;  ///< whose texts are being reworded
    int nextKey = 0;           ///< the how-manieth text of `owner`, its key in the memory

    /// Starts on the texts of `o`.
    void begin(QObject* o)
    {
        owner = o;
        nextKey = 0;
    }
    QString apply(const QString& text, const QStringList& contexts, int key)
    {
        const QString from = fromZh ? QStringLiteral("zh") : QStringLiteral("en");
        const QString to = toZh ? QStringLiteral("zh") : QStringLiteral("en");
        QVariantMap memory = owner ? owner->property(kWordedProperty).toMap() : QVariantMap();
        const QString slot = QString::number(key);
        const QVariantMap was = memory.value(slot).toMap();
        // What this text was before the last switch, if it is still what that switch set.
        QString out = was.value(from).toString() == text && was.contains(to)
            ? was.value(to).toString()
            : Retranslator::reword(text, contexts, fromZh ? QStringLiteral("zh_CN") : QStringLiteral("en"),
                                   toZh ? QStringLiteral("zh_CN") : QStringLiteral("en"));
        if (out != text) {
            ++changed;
            if (owner) {
                memory.insert(slot, QVariantMap{{from, text}, {to, out}});
                owner->setProperty(kWordedProperty, memory);
            }
        }
        return out;
    }
    /// An item of a combo, list or table: reworded unless it reads as a name (foreignWord).
    template <typename Get, typename Set>
    void item(const QStringList& contexts, Get get, Set set)
    {
        if (!foreignWord(get(), contexts, fromZh))
            field(contexts, get, set);
        else
            ++nextKey;  // the texts after it keep their keys
    }
    template <typename Get, typename Set>
    void field(const QStringList& contexts, Get get, Set set)
    {
        const int key = nextKey++;
        const QString text = get();
        if (text.isEmpty())
            return;
        const QString out = apply(text, contexts, key);
        if (out != text)
            set(out);
    }
};

void rewordPlot(QCustomPlot* plot, const QStringList& contexts, Rewording& r)
{
    for (QCPAxisRect* rect : plot->axisRects())
        for (QCPAxis* axis : rect->axes())
            r.field(contexts, [axis] { return axis->label(); }, [axis](const QString& s) { axis->setLabel(s); });
    for (int i = 0; i < plot->plottableCount(); ++i) {
        QCPAbstractPlottable* p = plot->plottable(i);
        r.field(contexts, [p] { return p->name(); }, [p](const QString& s) { p->setName(s); });
    }
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto* t = qobject_cast<QCPItemText*>(plot->item(i)))
            r.field(contexts, [t] { return t->text(); }, [t](const QString& s) { t->setText(s); });
    for (QCPLayoutElement* e : plot->plotLayout()->elements(true))
        if (auto* t = qobject_cast<QCPTextElement*>(e))
            r.field(contexts, [t] { return t->text(); }, [t](const QString& s) { t->setText(s); });
    plot->replot(QCustomPlot::rpQueuedReplot);
}

void rewordActions(QWidget* w, const QStringList& contexts, Rewording& r)
{
    for (QAction* a : w->actions()) {
        r.begin(a);
        r.field(contexts, [a] { return a->text(); }, [a](const QString& s) { a->setText(s); });
        r.field(contexts, [a] { return a->toolTip(); }, [a](const QString& s) { a->setToolTip(s); });
    }
}

void rewordWidget(QWidget* w, Rewording& r)
{
    const QStringList contexts = contextsOf(w);
    r.begin(w);
    r.field(contexts, [w] { return w->toolTip(); }, [w](const QString& s) { w->setToolTip(s); });
    r.field(contexts, [w] { return w->statusTip(); }, [w](const QString& s) { w->setStatusTip(s); });
    if (w->isWindow() || qobject_cast<QDockWidget*>(w))
        r.field(contexts, [w] { return w->windowTitle(); }, [w](const QString& s) { w->setWindowTitle(s); });
    rewordActions(w, contexts, r);
    r.begin(w);
    r.nextKey = 1000000;  // after its actions: its own texts again, under keys of their own
    // Texts a widget keeps aside to show later (the usual tooltip of a control that is
    // greyed out with its reason) are worded with the rest.
    for (const QByteArray& name : w->dynamicPropertyNames())
        if (w->property(name.constData()).typeId() == QMetaType::QString)
            r.field(contexts, [w, name] { return w->property(name.constData()).toString(); },
                    [w, name](const QString& s) { w->setProperty(name.constData(), s); });
    if (auto* l = qobject_cast<QLabel*>(w))
        r.field(contexts, [l] { return l->text(); }, [l](const QString& s) { l->setText(s); });
    if (auto* b = qobject_cast<QAbstractButton*>(w))
        r.field(contexts, [b] { return b->text(); }, [b](const QString& s) { b->setText(s); });
    if (auto* g = qobject_cast<QGroupBox*>(w))
        r.field(contexts, [g] { return g->title(); }, [g](const QString& s) { g->setTitle(s); });
    if (auto* e = qobject_cast<QLineEdit*>(w))
        r.field(contexts, [e] { return e->placeholderText(); }, [e](const QString& s) { e->setPlaceholderText(s); });
    if (auto* m = qobject_cast<QMenu*>(w))
        r.field(contexts, [m] { return m->title(); }, [m](const QString& s) { m->setTitle(s); });
    if (auto* p = qobject_cast<QProgressBar*>(w))  // "%v of %m tiles"
        r.field(contexts, [p] { return p->format(); }, [p](const QString& f) { p->setFormat(f); });
    if (auto* s = qobject_cast<QAbstractSpinBox*>(w))
        r.field(contexts, [s] { return s->specialValueText(); }, [s](const QString& t) { s->setSpecialValueText(t); });
    if (auto* s = qobject_cast<QDoubleSpinBox*>(w)) {
        r.field(contexts, [s] { return s->suffix(); }, [s](const QString& t) { s->setSuffix(t); });
        r.field(contexts, [s] { return s->prefix(); }, [s](const QString& t) { s->setPrefix(t); });
    }
    if (auto* s = qobject_cast<QSpinBox*>(w)) {
        r.field(contexts, [s] { return s->suffix(); }, [s](const QString& t) { s->setSuffix(t); });
        r.field(contexts, [s] { return s->prefix(); }, [s](const QString& t) { s->setPrefix(t); });
    }
    if (auto* c = qobject_cast<QComboBox*>(w)) {
        // A combo that lists names from a file (a recipe's plates) says so: a name that is
        // also a word of the screen ("samples") is still the name the file and the code
        // look it up by, and a rewording would lose it.
        const int items = c->property(Retranslator::kItemsAreNames).toBool() ? 0 : c->count();
        for (int i = 0; i < items; ++i) {
            // An item whose data is an id of its own (a step type) is a worded term; one with
            // no data, or its text as its data (a station, a plate), may be a name.
            const QVariant data = c->itemData(i);
            auto get = [c, i] { return c->itemText(i); };
            auto set = [c, i](const QString& s) { c->setItemText(i, s); };
            if (!data.isValid() || data.toString() == c->itemText(i))
                r.item(contexts, get, set);
            else
                r.field(contexts, get, set);
            r.field(contexts, [c, i] { return c->itemData(i, Qt::ToolTipRole).toString(); },
                    [c, i](const QString& s) { c->setItemData(i, s, Qt::ToolTipRole); });
        }
        if (c->lineEdit())
            r.field(contexts, [c] { return c->placeholderText(); }, [c](const QString& s) { c->setPlaceholderText(s); });
    }
    if (auto* t = qobject_cast<QTabWidget*>(w))
        for (int i = 0; i < t->count(); ++i) {
            r.field(contexts, [t, i] { return t->tabText(i); }, [t, i](const QString& s) { t->setTabText(i, s); });
            r.field(contexts, [t, i] { return t->tabToolTip(i); }, [t, i](const QString& s) { t->setTabToolTip(i, s); });
        }
    if (auto* t = qobject_cast<QTableWidget*>(w)) {
        auto items = [&](QTableWidgetItem* item) {
            if (!item)
                return;
            r.item(contexts, [item] { return item->text(); }, [item](const QString& s) { item->setText(s); });
            r.field(contexts, [item] { return item->toolTip(); }, [item](const QString& s) { item->setToolTip(s); });
        };
        for (int c = 0; c < t->columnCount(); ++c)
            items(t->horizontalHeaderItem(c));
        for (int row = 0; row < t->rowCount(); ++row) {
            items(t->verticalHeaderItem(row));
            for (int c = 0; c < t->columnCount(); ++c)
                items(t->item(row, c));
        }
    }
    if (auto* t = qobject_cast<QTreeWidget*>(w)) {
        QTreeWidgetItem* header = t->headerItem();
        for (int c = 0; header && c < header->columnCount(); ++c)
            r.field(contexts, [header, c] { return header->text(c); }, [header, c](const QString& s) { header->setText(c, s); });
        for (QTreeWidgetItemIterator it(t); *it; ++it)
            for (int c = 0; c < (*it)->columnCount(); ++c) {
                QTreeWidgetItem* item = *it;
                r.item(contexts, [item, c] { return item->text(c); }, [item, c](const QString& s) { item->setText(c, s); });
            }
    }
    if (auto* l = qobject_cast<QListWidget*>(w))
        for (int i = 0; i < l->count(); ++i) {
            QListWidgetItem* item = l->item(i);
            r.item(contexts, [item] { return item->text(); }, [item](const QString& s) { item->setText(s); });
            r.field(contexts, [item] { return item->toolTip(); }, [item](const QString& s) { item->setToolTip(s); });
        }
    if (auto* p = qobject_cast<QCustomPlot*>(w))
        rewordPlot(p, contexts, r);
}

} // namespace

namespace {

QString rewordIn(const QString& text, const QStringList& contexts, bool fromZh, bool toZh, int depth);

/// Exact or as a sentence with arguments (each argument reworded in turn); the text
/// itself when neither.
QString rewordWhole(const QString& text, const QStringList& contexts, bool fromZh, bool toZh, int depth)
{
    const Catalogue& cat = Catalogue::instance();
    const QVector<int>& exact = cat.exact(fromZh, text);
    if (!exact.isEmpty())
        return inLanguage(cat.entries()[static_cast<std::size_t>(pick(exact, contexts))], toZh);
    QVector<int> matched;
    QVector<QStringList> captures;
    for (const SentencePattern& p : cat.patterns(fromZh)) {
        if (!p.chunk.isEmpty() && !text.contains(p.chunk))
            continue;
        const auto m = p.re.match(text);
        if (!m.hasMatch())
            continue;
        matched.push_back(p.entry);
        QStringList args;
        for (int i = 1; i <= m.lastCapturedIndex(); ++i)
            args << m.captured(i);
        captures.push_back(args);
    }
    if (matched.isEmpty())
        return text;
    // The longest template is the most specific reading of the text.
    int best = 0;
    for (int i = 1; i < matched.size(); ++i) {
        const auto& a = cat.entries()[static_cast<std::size_t>(matched[i])];
        const auto& b = cat.entries()[static_cast<std::size_t>(matched[best])];
        if (inLanguage(a, fromZh).size() > inLanguage(b, fromZh).size())
            best = i;
    }
    const int chosen = pick(QVector<int>{matched[best]} + matched, contexts);
    const int at = static_cast<int>(matched.indexOf(chosen));
    const SentencePattern* pattern = nullptr;
    for (const SentencePattern& p : cat.patterns(fromZh))
        if (p.entry == chosen)
            pattern = &p;
    QString out = inLanguage(cat.entries()[static_cast<std::size_t>(chosen)], toZh);
    // Placeholders are filled in one pass, so an argument's own "%2" stays as it is.
    static const QRegularExpression holder(QStringLiteral("%L?[1-9]"));
    QString filled;
    int pos = 0;
    for (auto it = holder.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        filled += out.mid(pos, m.capturedStart() - pos);
        const QString number = m.captured().right(1);
        QString value = m.captured();
        for (int i = 0; pattern && i < pattern->holders.size(); ++i)
            if (pattern->holders[i].right(1) == number && i < captures[at].size()) {
                // An argument is often a worded text of its own ("Stage", a message).
                value = depth < 3 ? rewordIn(captures[at][i], contexts, fromZh, toZh, depth + 1) : captures[at][i];
                break;
            }
        filled += value;
        pos = m.capturedEnd();
    }
    filled += out.mid(pos);
    return filled;
}

/// A text the catalogue has neither whole nor as a sentence: the pieces between markup,
/// separators and line breaks, each on its own, and "Stage X" as a term and an axis.
QString rewordIn(const QString& text, const QStringList& contexts, bool fromZh, bool toZh, int depth)
{
    if (text.trimmed().isEmpty())
        return text;
    const QString whole = rewordWhole(text, contexts, fromZh, toZh, depth);
    if (whole != text)
        return whole;
    if (text.contains(QLatin1Char('\n')) && depth < 3) {
        // Line by line first: a reason above what a control does, a list of problems.
        QStringList lines = text.split(QLatin1Char('\n'));
        for (QString& line : lines)
            line = rewordIn(line, contexts, fromZh, toZh, depth + 1);
        return lines.join(QLatin1Char('\n'));
    }
    static const QRegularExpression axis(QStringLiteral("^(.+) ([A-Z])$"));
    if (const auto m = axis.match(text); m.hasMatch()) {
        const QString term = rewordWhole(m.captured(1), contexts, fromZh, toZh, depth);
        if (term != m.captured(1))
            return term + QLatin1Char(' ') + m.captured(2);
    }
    static const QRegularExpression cut(QStringLiteral("<[^>]*>|&[a-z]+;|\\s·\\s|\\s—\\s|\\s\\|\\s|\\n|:\\s|：|（|）"));
    QString out;
    int pos = 0;
    bool changed = false;
    auto piece = [&](const QString& part) {
        const int lead = static_cast<int>(part.size() - QString(part).remove(QRegularExpression(QStringLiteral("^\\s+"))).size());
        const QString core = part.trimmed();
        if (core.isEmpty() || depth >= 3) {
            out += part;
            return;
        }
        const QString done = rewordWhole(core, contexts, fromZh, toZh, depth + 1);
        changed = changed || done != core;
        out += part.left(lead) + done + part.mid(lead + core.size());
    };
    for (auto it = cut.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        piece(text.mid(pos, m.capturedStart() - pos));
        out += m.captured();
        pos = m.capturedEnd();
    }
    if (pos == 0)
        return text;
    piece(text.mid(pos));
    return changed ? out : text;
}

} // namespace

QString Retranslator::reword(const QString& text, const QStringList& contexts, const QString& from, const QString& to)
{
    const bool fromZh = isChinese(from), toZh = isChinese(to);
    if (fromZh == toZh || text.isEmpty())
        return text;
    return rewordIn(text, contexts, fromZh, toZh, 0);
}

int Retranslator::retranslate(const QList<QWidget*>& roots, const QString& from, const QString& to)
{
    Rewording r;
    r.fromZh = isChinese(from);
    r.toZh = isChinese(to);
    if (r.fromZh == r.toZh)
        return 0;
    for (QWidget* root : roots) {
        rewordWidget(root, r);
        for (QWidget* w : root->findChildren<QWidget*>())
            rewordWidget(w, r);
    }
    return r.changed;
}

} // namespace ui
