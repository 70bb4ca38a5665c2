// The one seam every question the window asks goes through: file and folder choosers, text and
// number prompts, yes/no/cancel questions and notes. The window uses Qt's modal dialogs; a test
// installs answers of its own (ScriptedDialogs) so it never blocks on a modal box.
#pragma once

#include <QMessageBox>
#include <QString>
#include <QStringList>

#include <optional>

class QDialog;
class QWidget;

namespace fieldsight::ui {

class Dialogs
{
public:
    virtual ~Dialogs() = default;

    /// The dialogs in use: Qt's own unless a test installed others.
    static Dialogs& current();
    /// Installs `dialogs` (not owned; null restores Qt's own); returns the ones installed before.
    static Dialogs* install(Dialogs* dialogs);

    /// An empty string when the user cancelled.
    virtual QString openFile(QWidget* parent, const QString& title, const QString& dir,
                             const QString& filter) = 0;
    virtual QString saveFile(QWidget* parent, const QString& title, const QString& suggestion,
                             const QString& filter) = 0;
    virtual QString folder(QWidget* parent, const QString& title, const QString& dir) = 0;
    /// Nothing when the user cancelled.
    virtual std::optional<QString> text(QWidget* parent, const QString& title, const QString& label,
                                        const QString& initial) = 0;
    virtual std::optional<int> number(QWidget* parent, const QString& title, const QString& label,
                                      int initial, int min, int max) = 0;
    /// One of `buttons`.
    virtual QMessageBox::StandardButton question(QWidget* parent, const QString& title,
                                                 const QString& text,
                                                 QMessageBox::StandardButtons buttons,
                                                 QMessageBox::StandardButton preferred) = 0;
    virtual void information(QWidget* parent, const QString& title, const QString& text) = 0;
    /// A long text (rich text: a table of the shortcuts) in a window that scrolls and fits the
    /// screen, with Close; by default as information().
    virtual void document(QWidget* parent, const QString& title, const QString& html)
    {
        information(parent, title, html);
    }
    /// One of `options` (its index), or -1 when the user cancelled; `preferred` is the default.
    virtual int choice(QWidget* parent, const QString& title, const QString& text,
                       const QStringList& options, int preferred) = 0;
};

/// The window Qt's document() shows (not yet shown): `html` in a scrolling text view, at most
/// 90% of the available screen high and wide, with a Close button.
QDialog* makeDocumentDialog(QWidget* parent, const QString& title, const QString& html);

} // namespace fieldsight::ui
