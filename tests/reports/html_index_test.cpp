// index.html of the reports: text is escaped (scene and case names come from
// other people), Markdown pipe tables become tables, plots become img tags.
#include <gtest/gtest.h>

#include <string>

#include "reports/html_index.h"

namespace {

using physdbg::reports::escapeHtml;
using physdbg::reports::htmlIndex;

TEST(HtmlIndex, EscapesEveryMarkupCharacter) {
  EXPECT_EQ(escapeHtml("<b>&\"x\"'</b>"), "&lt;b&gt;&amp;&quot;x&quot;&#39;&lt;/b&gt;");
}

TEST(HtmlIndex, TableCellsTitleAndImagesAreEscaped) {
  const std::string page = htmlIndex("a<title>", "# Head & shoulders\n\nsome <text>\n\n| case | result |\n| --- | --- |\n"
                                                 "| <script>alert(1)</script> | PASS |\n",
                                     {"x\".png"});
  EXPECT_EQ(page.find("<script>"), std::string::npos) << page;
  EXPECT_NE(page.find("<td>&lt;script&gt;alert(1)&lt;/script&gt;</td><td>PASS</td>"), std::string::npos) << page;
  EXPECT_NE(page.find("<th>case</th><th>result</th>"), std::string::npos) << page;
  EXPECT_NE(page.find("<title>a&lt;title&gt;</title>"), std::string::npos) << page;
  EXPECT_NE(page.find("<h1>Head &amp; shoulders</h1>"), std::string::npos) << page;
  EXPECT_NE(page.find("<p>some &lt;text&gt;</p>"), std::string::npos) << page;
  EXPECT_NE(page.find("<img src=\"x&quot;.png\""), std::string::npos) << page;
  EXPECT_EQ(page.find("---"), std::string::npos) << "the header rule is not a row: " << page;
}

}  // namespace
