"""What every page of a grading writes alike (no ROS): text escaped for HTML,
a page's head with the style every page shares, the script that counts a
page's missing pictures, and a figure as the pages show it."""
import html

# every page's look: a page adds its own rules after these
BASE_STYLE = ('body{font-family:sans-serif;margin:1.5em;color:#222}'
              'table{border-collapse:collapse}th,td{border:1px solid #ccc;padding:4px 8px;'
              'font-size:13px;vertical-align:top}th{background:#eee}pre{background:#f6f6f6;'
              'padding:8px;overflow-x:auto;font-size:12px;max-height:30em}.fail{color:#c62828}'
              '.ok{color:#2e7d32}.nj{color:#8a6d3b}img{border:1px solid #ddd}')
# every page counts the pictures the browser could not show, once loaded (tests read it)
IMAGES_JS = '''window.addEventListener('load',function(){var n=0;[].forEach.call(
document.images,function(i){if(!i.complete||!i.naturalWidth)n++;});
document.body.setAttribute('data-images-missing',n);});'''


def e(text):
    """``text`` (anything; None: nothing) escaped for HTML."""
    return html.escape(str(text if text is not None else ''))


def head(title, style='', script=''):
    """The start of a page: its title, the shared style and its own, and, if
    any, its script."""
    return ('<!DOCTYPE html><html><head><meta charset="utf-8"><title>%s</title>'
            '<style>%s%s</style>%s</head><body>' % (e(title), BASE_STYLE, style,
                                                  '<script>%s</script>' % script if script
                                                  else ''))


def figure(value, none='no figure'):
    """A check's figure as the pages show it: three significant digits."""
    if value is None:
        return none
    return ('%.3g' % value) if isinstance(value, float) else str(value)
