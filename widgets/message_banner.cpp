#include "widgets/message_banner.h"

#include "widgets/wording/wording.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QToolButton>

#include <algorithm>

namespace ui {
namespace {
/// `text` cut (with an ellipsis) to what `lines` word-wrapped lines of `width` pixels hold.
QString fitBannerLines(const QFontMetrics& fm, const QString& text, int width, int lines)
{
    const auto fits = [&](const QString& t) {
        return fm.boundingRect(QRect(0, 0, width, 1 << 20), Qt::TextWordWrap, t).height() <= lines * fm.lineSpacing() + 1;
    };
    if (width <= 0 || fits(text))
        return text;
    int lo = 0, hi = static_cast<int>(text.size());
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (fits(text.left(mid) + QStringLiteral("…")))
            lo = mid;
        else
            hi = mid - 1;
    }
    return text.left(lo).trimmed() + QStringLiteral("…");
}
} // namespace

MessageBanner::MessageBanner(QWidget* parent)
    : QFrame(parent), m_label(new QLabel(this)), m_more(new QLabel(this)), m_close(new QToolButton(this))
{
    setObjectName(QStringLiteral("messageBanner"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 2, 4, 2);
    // Two lines, whatever the text: the box's height never changes with its message.
    m_label->setWordWrap(true);
    m_label->setTextFormat(Qt::PlainText);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    layout->addWidget(m_label, 1);
    layout->addWidget(m_more);
    m_close->setText(QStringLiteral("✕"));
    m_close->setAutoRaise(true);
    layout->addWidget(m_close);
    connect(m_close, &QToolButton::clicked, this, &MessageBanner::dismiss);
    m_fade.setSingleShot(true);
    connect(&m_fade, &QTimer::timeout, this, [this] {
        if (m_shown.level != Level::Error)
            dismiss();
    });
    setFixedHeight(std::max(m_close->sizeHint().height(), kLines * fontMetrics().lineSpacing()) + 8);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    display({});
}

QString MessageBanner::text() const { return m_shown.text; }

QStringList MessageBanner::texts() const
{
    QStringList out;
    if (hasMessage())
        out << m_shown.text;
    for (const Entry& e : m_waiting)
        out << e.text;
    return out;
}

void MessageBanner::show(Level level, const QString& message, const QString& key)
{
    add(Entry{level, message, 1, key, {}});
}

void MessageBanner::show(Level level, const Wording& wording, const QString& key)
{
    add(Entry{level, wording ? wording() : QString(), 1, key, wording});
}

void MessageBanner::add(Entry e)
{
    if (e.text.isEmpty())
        return;
    e.text = ui::words::sentence(e.text);
    const QString& text = e.text;
    const Level level = e.level;
    if (hasMessage() && text == m_shown.text) {
        ++m_shown.count;
        m_shown.level = std::max(m_shown.level, level);
        display(m_shown);
        return;
    }
    for (Entry& w : m_waiting)
        if (w.text == text) {
            ++w.count;
            w.level = std::max(w.level, level);
            relabel();
            return;
        }
    // An unread error is not pushed out of sight by lesser news: that waits behind it.
    if (hasMessage() && m_shown.level == Level::Error && level != Level::Error) {
        m_waiting.append(e);
    } else {
        if (hasMessage() && m_shown.level == Level::Error)
            m_waiting.prepend(m_shown);  // the newer error first; the older one still waits to be read
        display(e);
    }
    while (m_waiting.size() > kMaxWaiting) {
        int drop = 0;
        for (int i = 0; i < m_waiting.size(); ++i)
            if (m_waiting[i].level != Level::Error) {
                drop = i;
                break;
            }
        m_waiting.removeAt(drop);
    }
    relabel();
}

void MessageBanner::withdraw(const QString& key)
{
    if (key.isEmpty())
        return;
    m_waiting.erase(std::remove_if(m_waiting.begin(), m_waiting.end(), [&](const Entry& e) { return e.key == key; }), m_waiting.end());
    if (hasMessage() && m_shown.key == key)
        dismiss();
    else
        relabel();
}

void MessageBanner::dismiss()
{
    display(m_waiting.isEmpty() ? Entry{} : m_waiting.takeFirst());
}

void MessageBanner::display(const Entry& e)
{
    m_shown = e;
    m_level = e.level;
    const char* style = e.text.isEmpty()         ? "background:transparent; border:1px solid transparent;"
        : e.level == Level::Error                ? "background:#fde2e1; color:#7a1212; border:1px solid #e5a3a1;"
        : e.level == Level::Warning              ? "background:#fff4d6; color:#6b4b00; border:1px solid #e8cf8a;"
                                                 : "background:#e4effd; color:#173d6b; border:1px solid #a9c6ec;";
    setStyleSheet(QStringLiteral("#messageBanner { %1 border-radius:4px; }").arg(QLatin1String(style)));
    // With nothing to say the box gives its width away (the connections' identities use it)
    // and keeps its height, so a message that comes or goes moves no control.
    setMaximumWidth(e.text.isEmpty() ? 0 : QWIDGETSIZE_MAX);
    // Errors wait for the operator; lesser news steps aside by itself.
    if (e.text.isEmpty() || e.level == Level::Error)
        m_fade.stop();
    else
        m_fade.start(kFadeMs);
    relabel();
}

void MessageBanner::relabel()
{
    const bool any = hasMessage();
    QString shown = m_shown.text;
    if (m_shown.count > 1)
        shown = tr("%1 (×%2)").arg(shown, QLocale().toString(m_shown.count));
    m_label->setToolTip(any ? shown : QString());
    const int room = std::max(0, m_label->width() - 4);
    m_label->setText(fitBannerLines(m_label->fontMetrics(), shown, room, kLines));
    m_more->setText(m_waiting.isEmpty() ? QString() : tr("+%1 more").arg(QLocale().toString(static_cast<int>(m_waiting.size()))));
    m_more->setVisible(!m_waiting.isEmpty());
    m_close->setToolTip(m_waiting.isEmpty() ? tr("Dismiss") : tr("Dismiss: show the next message"));
    // The button's place is kept while there is nothing to dismiss.
    QSizePolicy sp = m_close->sizePolicy();
    sp.setRetainSizeWhenHidden(true);
    m_close->setSizePolicy(sp);
    m_close->setVisible(any);
}

void MessageBanner::resizeEvent(QResizeEvent* event)
{
    QFrame::resizeEvent(event);
    relabel();
}

void MessageBanner::changeEvent(QEvent* event)
{
    QFrame::changeEvent(event);
    if (event->type() == QEvent::LanguageChange) {
        auto reword = [](Entry& e) {
            if (e.wording)
                e.text = ui::words::sentence(e.wording());
        };
        reword(m_shown);
        for (Entry& w : m_waiting)
            reword(w);
        relabel();
    }
}

} // namespace ui
