#pragma once
// An A4 PDF whose painter draws in millimetres, written all or nothing: what the
// accuracy and circle reports share.
#include <QPainter>
#include <QPdfWriter>
#include <QString>

#include <functional>

namespace ui::report {

class Document {
public:
    explicit Document(const QString& path);
    bool ok() const { return m_ok; }
    QPainter& painter() { return m_painter; }
    void newPage();
    int pageNumber() const { return m_page; }
    bool finish() { return m_painter.end(); }
    void setTitle(const QString& t) { m_writer.setTitle(t); }

private:
    QPdfWriter m_writer;
    QPainter m_painter;
    bool m_ok = false;
    int m_page = 1;
};

/// Renders into a temporary file beside `pdfPath` and renames it over at the end, so a
/// failure leaves no half-written report. False with a sentence in `error`, also when
/// there is no graphical application to render with (canRender).
bool writeAtomically(const QString& pdfPath, const std::function<bool(const QString& tempPath)>& render, QString* error);

} // namespace ui::report
