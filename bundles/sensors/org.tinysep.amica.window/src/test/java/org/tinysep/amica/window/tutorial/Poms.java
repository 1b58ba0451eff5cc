package org.tinysep.amica.window.tutorial;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.xpath.XPathConstants;
import javax.xml.xpath.XPathFactory;
import org.w3c.dom.Document;
import org.w3c.dom.NodeList;

/** XPath look-ups in Maven poms (namespaces ignored). */
final class Poms {

    private Poms() {
    }

    /** @return the text of the single node {@code xpath} selects; fails if there is none */
    static String text(Path pom, String xpath) throws Exception {
        List<String> all = texts(pom, xpath);
        if (all.size() != 1) {
            throw new AssertionError(pom + ": " + all.size() + " nodes at " + xpath);
        }
        return all.get(0);
    }

    /** @return the texts of every node {@code xpath} selects (the file must be well-formed XML) */
    static List<String> texts(Path pom, String xpath) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(false);
        Document doc = f.newDocumentBuilder().parse(pom.toFile());
        NodeList nodes = (NodeList) XPathFactory.newInstance().newXPath().evaluate(xpath, doc, XPathConstants.NODESET);
        List<String> out = new ArrayList<>();
        for (int i = 0; i < nodes.getLength(); i++) {
            out.add(nodes.item(i).getTextContent().strip());
        }
        return out;
    }
}
