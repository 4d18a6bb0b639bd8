#include "widgets/message_banner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace ui {

MessageBanner::MessageBanner(QWidget* parent) : QFrame(parent), m_label(new QLabel(this))
{
    setObjectName(QStringLiteral("messageBanner"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(10, 4, 4, 4);
    m_label->setWordWrap(true);
    m_label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_label, 1);
    auto* close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setToolTip(tr("Dismiss"));
    close->setAutoRaise(true);
    layout->addWidget(close);
    connect(close, &QToolButton::clicked, this, &QWidget::hide);
    m_hide.setSingleShot(true);
    connect(&m_hide, &QTimer::timeout, this, &QWidget::hide);
    hide();
}

QString MessageBanner::text() const { return m_label->text(); }

void MessageBanner::show(Level level, const QString& text)
{
    m_level = level;
    const char* style = level == Level::Error ? "background:#fde2e1; color:#7a1212; border:1px solid #e5a3a1;"
        : level == Level::Warning            ? "background:#fff4d6; color:#6b4b00; border:1px solid #e8cf8a;"
                                             : "background:#e4effd; color:#173d6b; border:1px solid #a9c6ec;";
    setStyleSheet(QStringLiteral("#messageBanner { %1 border-radius:4px; }").arg(QLatin1String(style)));
    m_label->setText(text);
    QFrame::show();
    // Errors wait for the operator; lesser news steps aside by itself.
    if (level == Level::Error)
        m_hide.stop();
    else
        m_hide.start(8000);
}

} // namespace ui
